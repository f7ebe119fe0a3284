"""The plugin in the real MeshLab 2020.09 GUI under Xvfb (issue 3, bullet 4, last point).

Starts the private prefix's meshlab on a sample with patch ids, finds the filter through the
GUI's filter search (Ctrl+F, which lists the actions of the Filters menu), opens its dialog,
presses Apply and checks the screenshots (saved in the test's tmp dir): the grey input becomes
coloured by the ramp.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from ml2020_support import FILTER_NAME, REPO

SCREEN = (1280, 1024)
WINDOW = (1200, 900)          # the main window is resized to this, at the top-left corner
VIEWPORT = (10, 80, 700, 700)  # left, top, right, bottom of the 3D view inside WINDOW


class Display:
    """A private Xvfb server and the commands run on it."""

    def __init__(self, workdir: Path):
        read_fd, write_fd = os.pipe()
        self.server = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{SCREEN[0]}x{SCREEN[1]}x24", "-nolisten", "tcp"],
            pass_fds=(write_fd,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write_fd)
        with os.fdopen(read_fd) as pipe:
            number = pipe.readline().strip()
        assert number, "Xvfb did not start"
        self.env = dict(os.environ, DISPLAY=f":{number}", HOME=str(workdir))
        self.apps: list[subprocess.Popen] = []

    def start(self, cmd: list[str], log: Path) -> subprocess.Popen:
        app = subprocess.Popen(cmd, env=self.env, stdout=log.open("w"), stderr=subprocess.STDOUT)
        self.apps.append(app)
        return app

    def xdotool(self, *args: str) -> str:
        return subprocess.run(["xdotool", *args], env=self.env, capture_output=True, text=True,
                              check=False).stdout

    def window(self, name: str, timeout: float = 60) -> str:
        end = time.time() + timeout
        while time.time() < end:
            ids = self.xdotool("search", "--name", name).split()
            if ids:
                return ids[0]
            time.sleep(0.5)
        raise AssertionError(f"no window named '{name}' after {timeout} s")

    def geometry(self, window: str) -> dict[str, int]:
        lines = self.xdotool("getwindowgeometry", "--shell", window).split()
        return {k: int(v) for k, v in (line.split("=") for line in lines) if k in {"X", "Y", "WIDTH", "HEIGHT"}}

    def click(self, x: int, y: int) -> None:
        self.xdotool("mousemove", str(x), str(y), "click", "1")

    def screenshot(self, path: Path) -> np.ndarray:
        subprocess.run(["import", "-window", "root", str(path)], env=self.env, check=True)
        return np.asarray(Image.open(path).convert("RGB"), dtype=np.int64)

    def close(self) -> None:
        for app in self.apps + [self.server]:
            app.terminate()
            try:
                app.wait(timeout=10)
            except subprocess.TimeoutExpired:
                app.kill()


def warm_pixels(image: np.ndarray) -> int:
    """Pixels of the 3D view clearly red, yellow or green: the ramp's colours, absent from the grey
    mesh and the blue background."""
    left, top, right, bottom = VIEWPORT
    view = image[top:bottom, left:right]
    return int(((np.maximum(view[..., 0], view[..., 1]) - view[..., 2]) > 80).sum())


def wait_for(predicate, timeout: float, what: str) -> None:
    end = time.time() + timeout
    while time.time() < end:
        if predicate():
            return
        time.sleep(0.5)
    raise AssertionError(f"timed out after {timeout} s waiting for {what}")


@pytest.fixture
def display(tmp_path):
    for tool in ("Xvfb", "xdotool", "import"):
        assert shutil.which(tool), f"{tool} missing: run scripts/setup.sh"
    d = Display(tmp_path)
    yield d
    d.close()


def test_gui_menu_entry_dialog_and_colours(display, meshlab_prefix, tmp_path):
    mesh = tmp_path / "patches.ply"
    shutil.copy(REPO / "sample_meshes" / "patches.ply", mesh)
    log = tmp_path / "meshlab.log"
    display.start([str(meshlab_prefix / "bin" / "meshlab"), str(mesh)], log)
    main = display.window("MeshLab 2020.09")
    display.xdotool("windowmove", main, "0", "0")
    display.xdotool("windowsize", main, str(WINDOW[0]), str(WINDOW[1]))
    wait_for(lambda: "Opened mesh" in log.read_text() or "All files opened" in log.read_text(), 60,
             "the mesh to load")
    time.sleep(2)
    before = display.screenshot(tmp_path / "gui_before.png")

    display.xdotool("windowfocus", "--sync", main)  # no window manager: set the focus directly
    display.xdotool("key", "ctrl+f")           # the filter search of the Filters menu's actions
    time.sleep(1)
    display.xdotool("type", "--delay", "40", "Quasi-Developable")
    time.sleep(1)
    display.screenshot(tmp_path / "gui_search.png")
    display.xdotool("key", "Down")
    display.xdotool("key", "Return")
    dialog = display.window(f"^{FILTER_NAME}$", timeout=20)
    display.screenshot(tmp_path / "gui_dialog.png")
    g = display.geometry(dialog)
    display.click(g["X"] + g["WIDTH"] * 3 // 4, g["Y"] + g["HEIGHT"] - 24)      # Apply
    wait_for(lambda: f"Applied filter {FILTER_NAME}" in log.read_text()
             or "failed:" in log.read_text(), 300, "the filter to finish")
    assert f"Applied filter {FILTER_NAME}" in log.read_text(), log.read_text()[-3000:]
    display.click(g["X"] + g["WIDTH"] // 4, g["Y"] + g["HEIGHT"] - 24)          # Close
    time.sleep(2)
    after = display.screenshot(tmp_path / "gui_after.png")

    print(f"screenshots in {tmp_path}")
    assert warm_pixels(before) < 500, f"input not grey? see {tmp_path / 'gui_before.png'}"
    assert warm_pixels(after) > 5000, f"mesh not coloured: see {tmp_path / 'gui_after.png'}"
