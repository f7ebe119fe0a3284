"""The real MeshLab GUI under Xvfb, driven like a user: shared by the GUI tests of both MeshLab
generations (test_gui.py: 2020.09 on the host; test_gui_2025.py: 2025.07 in the Debian sid
chroot of scripts/setup_sid_chroot.sh).

All input goes through X (xdotool: clicks, keys, typing); what the GUI shows is read from
screenshots (ImageMagick `import`), MeshLab's log on stdout, the files it saves, and a read-only
probe (gui_probe.cpp, LD_PRELOAD'ed) that writes every visible window's titles, labels, buttons,
fields and menu entries with their screen positions, so the tests check the texts a user sees and
click a button where it really is.

`exercise_filter` is the one scenario both generations run: open the mesh, find the filter in
its Filters submenu (the flattening filter under Filters > Texture, the segmentation under Filters
> Quality Measure and Computations) and all three through the filter search (Ctrl+F), open the
approximation's dialog from the menu, read
the dialog, press Apply, wait for MeshLab's "Applied filter" log line, close the dialog and
export the mesh through File > Export Mesh As. `check_dialog` and `check_filter_result` then
check the dialog's labels and the saved mesh against the input; `run_and_check` is the two
tests' common body. A message box (e.g. MeshLab 2025.07's "Unable to load the following plugins")
at any point fails the run with its text.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
from PIL import Image

from ml2020_support import (FILTER_NAME, FLATTEN_FILTER_NAME, REPO, SEGMENT_FILTER_NAME, Mesh, boundary_vertices,
                            declared_parameters, integrated_curvature, load_mesh, mlx_parameters, seam_vertices)

SCREEN = (1280, 1024)
WINDOW = (1200, 900)           # the main window is moved to the top-left corner and resized to this
VIEWPORT = (10, 80, 700, 700)  # left, top, right, bottom of the 3D view inside WINDOW (both versions)
MENU = "Smoothing, Fairing and Deformation"   # the Filters submenu that lists our filter
FLATTEN_MENU = "Texture"                      # the one that lists the flattening, in both versions
SEGMENT_MENU = "Quality Measure and Computations"  # the segmentation's (FilterClass Quality), in both
PROBE_SOURCE = Path(__file__).with_name("gui_probe.cpp")


def wait_for(predicate: Callable[[], object], timeout: float, what: str, poll: float = 0.25):
    """predicate()'s first truthy value; fails after timeout seconds."""
    end = time.time() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.time() > end:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(poll)


def stop_process(process: subprocess.Popen) -> None:
    """SIGTERM, then SIGKILL after 10 s."""
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def build_probe(dest_dir: Path) -> Path:
    """Compiles gui_probe.cpp against the host's Qt 5 into dest_dir/libqd_gui_probe.so."""
    out = dest_dir / "libqd_gui_probe.so"
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", "Qt5Widgets"], capture_output=True,
                           text=True, check=False)
    assert flags.returncode == 0, f"pkg-config Qt5Widgets failed (run scripts/setup.sh): {flags.stderr}"
    done = subprocess.run(["g++", "-std=c++17", "-O1", "-shared", "-fPIC", "-o", str(out),
                           str(PROBE_SOURCE), *flags.stdout.split()],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, f"building {PROBE_SOURCE.name} failed:\n{done.stderr}"
    return out


class Display:
    """A private Xvfb server and the X commands run on it."""

    def __init__(self, workdir: Path):
        for tool in ("Xvfb", "xdotool", "import"):
            assert shutil.which(tool), f"{tool} missing: run scripts/setup.sh"
        read_fd, write_fd = os.pipe()
        self.server = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{SCREEN[0]}x{SCREEN[1]}x24",
             "-nolisten", "tcp"],
            pass_fds=(write_fd,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write_fd)
        with os.fdopen(read_fd) as pipe:
            self.number = pipe.readline().strip()
        assert self.number, "Xvfb did not start"
        self.name = f":{self.number}"
        self.env = dict(os.environ, DISPLAY=self.name, HOME=str(workdir))

    def xdotool(self, *args: str) -> str:
        return subprocess.run(["xdotool", *args], env=self.env, capture_output=True, text=True,
                              check=False).stdout

    def x_window(self, name: str) -> str:
        """The X id of a visible window whose name matches the regular expression, or ''."""
        ids = self.xdotool("search", "--onlyvisible", "--name", name).split()
        return ids[0] if ids else ""

    def click(self, x: int, y: int) -> None:
        self.xdotool("mousemove", str(x), str(y), "click", "1")

    def key(self, *keys: str) -> None:
        self.xdotool("key", "--delay", "60", *keys)

    def type(self, text: str) -> None:
        self.xdotool("type", "--delay", "40", text)

    def screenshot(self, path: Path) -> np.ndarray:
        subprocess.run(["import", "-window", "root", str(path)], env=self.env, check=True)
        return np.asarray(Image.open(path).convert("RGB"), dtype=np.int64)

    def close(self) -> None:
        stop_process(self.server)


@dataclass
class Widget:
    cls: str
    text: str
    x: int
    y: int
    checked: bool | None = None
    submenu: bool = False


@dataclass
class Window:
    title: str
    cls: str
    x: int
    y: int
    width: int
    height: int
    widgets: list[Widget] = field(default_factory=list)

    def texts(self, cls: str | None = None) -> list[str]:
        return [w.text for w in self.widgets if cls is None or w.cls == cls]

    def find(self, text: str, cls: str | None = None) -> Widget | None:
        return next((w for w in self.widgets if w.text == text and (cls is None or w.cls == cls)), None)

    def describe(self) -> str:
        return f"{self.cls} '{self.title}': " + " | ".join(t for t in self.texts() if t)


@dataclass
class MeshLabApp:
    """What differs between the two MeshLab generations under test."""
    version: str                        # "2020.09", "2025.07": the main window's title starts "MeshLab <version>"
    # (mesh as the app sees it, the app's environment) -> the command line run on the host, which
    # gives the app that environment (and only the app: LD_PRELOAD is the probe's path as the
    # app sees it)
    command: Callable[[Path, dict[str, str]], list[str]]
    app_path: Callable[[Path], Path]    # a path in the work dir as the app sees it
    applied_line: str                   # MeshLab's log line once our filter has run


class MeshLabGui:
    """One running MeshLab GUI on a Display: its process, log and probe."""

    def __init__(self, display: Display, app: MeshLabApp, workdir: Path, probe_lib: Path):
        self.display, self.app, self.workdir = display, app, workdir
        self.log = workdir / "meshlab.log"
        self.probe_file = workdir / "probe.json"
        lib = workdir / probe_lib.name
        if lib != probe_lib:
            shutil.copy(probe_lib, lib)
        self.env = {"DISPLAY": display.name, "HOME": str(app.app_path(workdir / "home")),
                    "LD_PRELOAD": str(app.app_path(lib)),
                    "QD_GUI_PROBE": str(app.app_path(self.probe_file))}
        (workdir / "home").mkdir(exist_ok=True)
        self.process: subprocess.Popen | None = None

    # ---- process and log ----------------------------------------------------------------------

    def start(self, mesh: Path) -> None:
        argv = self.app.command(self.app.app_path(mesh), self.env)
        self.process = subprocess.Popen(argv, stdout=self.log.open("w"), stderr=subprocess.STDOUT)

    def stop(self) -> None:
        if self.process:
            stop_process(self.process)

    def log_text(self) -> str:
        return self.log.read_text(errors="replace") if self.log.exists() else ""

    def check_running(self) -> None:
        """Fails if MeshLab has exited or shows a message box."""
        if self.process.poll() is not None:
            raise AssertionError(f"MeshLab {self.app.version} exited with {self.process.returncode}; "
                                 f"log:\n{self.log_text()[-3000:]}")
        self.check_no_message_box()

    # ---- what is shown ------------------------------------------------------------------------

    def windows(self) -> list[Window]:
        try:
            raw = json.loads(self.probe_file.read_text())
        except (FileNotFoundError, json.JSONDecodeError):
            return []
        return [Window(w["title"], w["class"], w["x"], w["y"], w["width"], w["height"],
                       [Widget(x["class"], x["text"], x["x"], x["y"], x.get("checked"), x.get("submenu", False))
                        for x in w["widgets"]])
                for w in raw]

    def check_no_message_box(self) -> None:
        boxes = [w for w in self.windows() if w.cls == "QMessageBox"]
        assert not boxes, "MeshLab shows a message box: " + "; ".join(b.describe() for b in boxes)

    def wait_window(self, title: str | None = None, cls: str | None = None, timeout: float = 30,
                    where: Callable[[Window], bool] = lambda w: True) -> Window:
        """The first visible window whose title matches the regular expression and whose Qt class
        is cls; fails at once if MeshLab exits or shows a message box."""
        def found():
            self.check_running()
            return next((w for w in self.windows()
                         if (title is None or re.search(title, w.title)) and (cls is None or w.cls == cls)
                         and where(w)), None)
        return self.wait(found, timeout, f"a window title={title!r} class={cls!r}")

    def wait(self, predicate: Callable[[], object], timeout: float, what: str):
        """wait_for, failing with the windows shown and a screenshot (timeout.png in the work dir)."""
        try:
            return wait_for(predicate, timeout, what)
        except AssertionError as timeout_error:
            shot = self.workdir / "timeout.png"
            self.display.screenshot(shot)
            shown = "\n  ".join(w.describe()[:300] + f" at ({w.x}, {w.y}) {w.width}x{w.height}"
                                for w in self.windows())
            raise AssertionError(f"{timeout_error}; shown (see {shot}):\n  {shown}") from None

    def wait_log(self, text: str, timeout: float, failure: str | None = None) -> str:
        def seen():
            self.check_running()
            log = self.log_text()
            if failure and failure in log:
                raise AssertionError(f"MeshLab logged '{failure}':\n{log[-3000:]}")
            return log if text in log else ""
        return self.wait(seen, timeout, f"'{text}' in MeshLab's log")

    # ---- input --------------------------------------------------------------------------------

    def click(self, widget: Widget) -> None:
        self.display.click(widget.x, widget.y)

    def click_text(self, window: Window, text: str, cls: str | None = None) -> None:
        widget = window.find(text, cls)
        assert widget, f"no '{text}' in {window.describe()}"
        self.click(widget)

    def focus_3d_view(self, main: Window) -> None:
        """Clicks into the 3D view: there is no window manager to give the main window the focus
        (`xdotool windowfocus` fails with BadMatch on 2025.07), and a click does."""
        self.display.click(main.x + VIEWPORT[0] + 150, main.y + VIEWPORT[1] + 150)
        time.sleep(0.3)


def warm_pixels(image: np.ndarray, main: Window) -> int:
    """Pixels of the 3D view clearly red, yellow or green: the ramp's colours, absent from the grey
    mesh and the blue background."""
    left, top, right, bottom = VIEWPORT
    view = image[main.y + top:main.y + bottom, main.x + left:main.x + right]
    return int(((np.maximum(view[..., 0], view[..., 1]) - view[..., 2]) > 80).sum())


@dataclass
class GuiRun:
    """What exercise_filter saw."""
    menu_entries: list[str]   # the Filters > MENU submenu
    search_entries: list[str]  # the filter search's results for "Quasi-Developable"
    dialog: Window
    log: str
    warm_before: int
    warm_after: int
    saved: Path


def open_filter_submenu(gui: MeshLabGui, main: Window, menu: str = MENU) -> Window:
    """Opens Filters > menu by clicks (hovering opens no submenu without a window manager)."""
    gui.focus_3d_view(main)
    gui.click_text(main, "Fi&lters", "QAction")
    filters = gui.wait_window(cls="QMenu", where=lambda w: w.find(menu, "QAction") is not None)
    gui.click_text(filters, menu, "QAction")
    return gui.wait_window(where=lambda w: w.cls != "MainWindow" and w.find(menu) is None
                           and len(w.texts("QAction")) > 3)


def exercise_filter(gui: MeshLabGui, mesh: Path, shots: Path) -> GuiRun:
    """The scenario of the module docstring on a not yet started `gui`; screenshots go to
    shots/gui_*.png, the exported mesh to exported.ply beside `mesh`."""
    d = gui.display
    gui.start(mesh)
    title = f"^MeshLab {re.escape(gui.app.version)}"
    gui.wait_window(title, cls="MainWindow", timeout=90)
    gui.wait_log("Opened mesh", 60)
    x_main = gui.wait(lambda: d.x_window(title), 10, "the main X window")

    def placed():   # MeshLab may still resize its window while starting: place it until it stays
        gui.check_running()
        d.xdotool("windowmove", x_main, "0", "0")
        d.xdotool("windowsize", x_main, str(WINDOW[0]), str(WINDOW[1]))
        time.sleep(0.6)
        return next((w for w in gui.windows() if w.cls == "MainWindow"
                     and (w.x, w.y, w.width, w.height) == (0, 0, *WINDOW)), None)
    main = gui.wait(placed, 30, f"the main window at (0, 0) with size {WINDOW}")
    time.sleep(2)   # the first frames
    warm_before = warm_pixels(d.screenshot(shots / "gui_before.png"), main)

    # Filters > MENU lists the filter.
    submenu = open_filter_submenu(gui, main)
    d.screenshot(shots / "gui_menu.png")
    menu_entries = submenu.texts("QAction")
    assert FILTER_NAME in menu_entries, f"'{FILTER_NAME}' not under Filters > {MENU}: {menu_entries}"
    d.key("Escape", "Escape")
    time.sleep(0.5)
    for menu, name, shot in ((FLATTEN_MENU, FLATTEN_FILTER_NAME, "gui_texture_menu.png"),
                             (SEGMENT_MENU, SEGMENT_FILTER_NAME, "gui_quality_menu.png")):
        entries = open_filter_submenu(gui, main, menu).texts("QAction")
        d.screenshot(shots / shot)
        assert name in entries, f"'{name}' not under Filters > {menu}: {entries}"
        d.key("Escape", "Escape")
        time.sleep(0.5)

    # The filter search (Ctrl+F) finds it.
    gui.focus_3d_view(main)
    d.key("ctrl+f")
    gui.wait_window(cls="SearchMenu", timeout=10)
    d.type("Quasi-Developable")
    search = gui.wait_window(cls="SearchMenu", where=lambda w: len(w.texts("QAction")) > 0, timeout=10)
    d.screenshot(shots / "gui_search.png")
    search_entries = search.texts("QAction")
    d.key("Escape")
    time.sleep(0.5)

    # Open the dialog from the menu, read it, Apply.
    gui.click_text(open_filter_submenu(gui, main), FILTER_NAME, "QAction")
    dialog = gui.wait_window(f"^{re.escape(FILTER_NAME)}$", where=lambda w: w.find("Apply") is not None)
    time.sleep(0.5)
    dialog = gui.wait_window(f"^{re.escape(FILTER_NAME)}$")
    d.screenshot(shots / "gui_dialog.png")
    gui.click_text(dialog, "Apply", "QPushButton")
    gui.wait_log(gui.app.applied_line, 300, failure=f"{FILTER_NAME} failed")
    gui.click_text(dialog, "Close", "QPushButton")
    gui.wait(lambda: not any(w.title == FILTER_NAME for w in gui.windows()), 10, "the dialog to close")
    time.sleep(2)
    warm_after = warm_pixels(d.screenshot(shots / "gui_after.png"), main)

    # File > Export Mesh As (Ctrl+Shift+E): the file dialog opens in the mesh's folder; a name
    # without a match there (the dialog completes names) and Return; then the saving options.
    saved = mesh.parent / "exported.ply"
    gui.focus_3d_view(main)
    d.key("ctrl+shift+e")
    gui.wait_window("^Save .* Layer$", timeout=20)
    d.key("ctrl+a")
    d.type(saved.name)
    d.key("Return")
    options = gui.wait_window("^Choose Saving Options", timeout=20, where=lambda w: w.find("OK") is not None)
    d.screenshot(shots / "gui_save_options.png")
    gui.click_text(options, "OK", "QPushButton")
    gui.wait_log("Saved Mesh", 30)
    assert saved.is_file(), f"MeshLab logged 'Saved Mesh' but {saved} is missing:\n{gui.log_text()[-2000:]}"
    gui.check_no_message_box()
    return GuiRun(menu_entries, search_entries, dialog, gui.log_text(), warm_before, warm_after, saved)


def check_dialog(dialog: Window) -> None:
    """The dialog shows every parameter's label, in order: the declared labels of the filter's
    parameters (qd_reference --json), whose names are those of sample_meshes/default.mlx."""
    declared = [p for p in declared_parameters("approximate") if p["fronts"] != "command"]
    names = list(mlx_parameters(REPO / "sample_meshes" / "default.mlx"))
    assert names == [p["name"] for p in declared], f"default.mlx has {names}, declared: {declared}"
    expected = [p["label"] for p in declared]
    shown = [t for t in dialog.texts() if t in expected]
    assert shown == expected, f"the dialog shows {shown}, expected {expected}: {dialog.describe()}"


def check_filter_result(run: GuiRun, mesh_in: Path, shots: Path) -> Mesh:
    """The exported mesh is the input with moved vertices (defaults: open boundary and seams kept),
    less curvature inside the patches, and the colour ramp; the screenshots show the ramp."""
    before, after = load_mesh(mesh_in), load_mesh(run.saved)
    assert after.v.shape == before.v.shape and np.array_equal(after.f, before.f), "connectivity changed"
    moved = np.linalg.norm(after.v - before.v, axis=1)
    diag = before.diagonal()
    assert moved.max() > 1e-3 * diag, f"no vertex moved (max {moved.max():.3g})"
    kept = boundary_vertices(before) | seam_vertices(before)
    assert kept.any() and moved[kept].max() <= 1e-6 * diag, \
        f"boundary/seam vertices moved by up to {moved[kept].max():.3g}"
    inner = ~kept
    k_before, k_after = integrated_curvature(before, inner), integrated_curvature(after, inner)
    assert k_after < 0.95 * k_before, f"curvature inside the patches {k_before:.4g} -> {k_after:.4g}"
    assert after.color is not None and after.quality is not None, "no vertex colour/quality saved"
    assert len(np.unique(after.color, axis=0)) > 10, "the vertex colours are not a ramp"
    assert run.warm_before < 500, f"input not grey? see {shots / 'gui_before.png'}"
    assert run.warm_after > 5000, f"mesh not coloured: see {shots / 'gui_after.png'}"
    return after


def run_and_check(gui: MeshLabGui, workdir: Path) -> GuiRun:
    """Both generations' test: exercise_filter on sample_meshes/patches.ply (copied to workdir),
    then the search result, the dialog and the result are checked."""
    mesh = workdir / "patches.ply"
    shutil.copy(REPO / "sample_meshes" / "patches.ply", mesh)
    run = exercise_filter(gui, mesh, workdir)
    print(f"screenshots in {workdir}")
    for name in (FILTER_NAME, SEGMENT_FILTER_NAME, FLATTEN_FILTER_NAME):
        assert name in run.search_entries, f"the filter search does not find '{name}': {run.search_entries}"
    check_dialog(run.dialog)
    check_filter_result(run, mesh, workdir)
    return run
