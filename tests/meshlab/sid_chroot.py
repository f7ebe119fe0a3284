"""The Debian sid chroot with MeshLab 2025.07 (made by scripts/setup_sid_chroot.sh) and how the
tests run a program in it.

`command()` runs a program inside the chroot from a private mount namespace (`unshare --mount`):
/dev, /proc, the X socket directory and the test's work directory (as /qd) are mounted there
only, so they vanish with the program, whatever happens to the test. `mounts_under()` lets the
fixtures check that nothing is left mounted in the chroot (which would make `rm -rf` of the clone
descend into /dev and /proc), and `unmount_all()` clears anything that is.
"""
from __future__ import annotations

import os
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
CHROOT = Path(os.environ.get("QD_SID_CHROOT", REPO / "third_party" / "sid-chroot"))
MARKER = CHROOT / ".qd-complete"
UNAVAILABLE = CHROOT.parent / (CHROOT.name + ".unavailable")
MESHLAB_VERSION = "2025.07"
SYSTEM_PLUGINS = Path("usr/lib/x86_64-linux-gnu/meshlab/plugins")        # inside the chroot
USER_PLUGINS = Path(".local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins") / MESHLAB_VERSION  # in $HOME
WORK = Path("/qd")   # the test's work directory inside the chroot

_MOUNT_AND_RUN = r"""
set -e
root=$1 work=$2; shift 2
mkdir -p "$root/tmp/.X11-unix" "$root/qd"
mount --rbind /dev "$root/dev"
mount -t proc proc "$root/proc"
mount --bind /tmp/.X11-unix "$root/tmp/.X11-unix"
mount --bind "$work" "$root/qd"
exec chroot "$root" "$@"
"""


def command(workdir: Path, env: dict[str, str], argv: list[str]) -> list[str]:
    """argv run in the chroot with only `env` (plus PATH), workdir mounted at /qd."""
    return ["unshare", "--mount", "--propagation", "private", "sh", "-c", _MOUNT_AND_RUN, "sh",
            str(CHROOT), str(workdir), "env", "-i", "PATH=/usr/sbin:/usr/bin:/sbin:/bin",
            *(f"{k}={v}" for k, v in env.items()), *argv]


def app_path(workdir: Path, path: Path) -> Path:
    """A path under workdir as seen inside the chroot."""
    return WORK / Path(path).relative_to(workdir)


def mounts_under(root: Path = CHROOT) -> list[str]:
    """Mount points at or below root in this process's mount namespace (deepest first)."""
    root = str(Path(root).resolve())
    points = []
    for line in Path("/proc/self/mountinfo").read_text().splitlines():
        point = line.split()[4].replace("\\040", " ")
        if point == root or point.startswith(root + "/"):
            points.append(point)
    return sorted(points, key=len, reverse=True)


def unmount_all(root: Path = CHROOT) -> list[str]:
    """Lazily unmounts everything below root; returns what was mounted."""
    points = mounts_under(root)
    for point in points:
        subprocess.run(["umount", "-l", point], check=False)
    return points
