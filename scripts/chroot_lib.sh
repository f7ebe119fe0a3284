# Sourced by scripts/setup_sid_chroot.sh and scripts/test_wheel.sh: the one recipe by which the
# project makes and uses its cached Debian chroots (the MeshLab 2025.07 GUI's sid chroot, the
# wheel test's bookworm chroot). The caller defines die MESSAGE (prints and exits) and runs as
# root.
#
# A chroot DIR is made in DIR.tmp and renamed when complete, with DIR/.qd-complete holding the
# caller's SPEC, so an interrupted run leaves no half chroot behind the marker. Every mount
# (debootstrap's /proc and /sys, the commands' /proc, /tmp and binds) happens inside a private
# mount namespace (unshare -m) that dies with its command: nothing stays mounted under DIR,
# whatever happens, so `rm -rf` of the clone always works.

# chroot_complete DIR SPEC: true when DIR is a finished chroot made for SPEC.
chroot_complete() {
  [ -f "$1/.qd-complete" ] && [ "$(cat "$1/.qd-complete")" = "$2" ]
}

# chroot_remove DIR: deletes DIR, but refuses when something is mounted in it (rm -rf would
# descend into its /proc or /dev).
chroot_remove() {
  [ -e "$1" ] || return 0
  local real
  real="$(realpath "$1")"
  if findmnt -rno TARGET | awk -v d="$real" '$0 == d || index($0, d "/") == 1 {f = 1} END {exit !f}'; then
    die "something is mounted under $real (see findmnt -R $real): unmount it, then rerun"
  fi
  rm -rf "$1"
}

# chroot_bootstrap SUITE DIR MIRROR: removes DIR and DIR.tmp, then debootstraps a minbase SUITE
# into DIR.tmp without documentation, manual pages or translations (a third of the size), with
# a file on which chroot_run binds the host's resolv.conf.
chroot_bootstrap() {
  local suite="$1" tmp="$2.tmp" mirror="$3"
  command -v debootstrap >/dev/null || die "debootstrap missing (apt-get install debootstrap)"
  chroot_remove "$tmp"
  chroot_remove "$2"
  mkdir -p "$(dirname "$2")"
  unshare --mount --propagation private \
    debootstrap --variant=minbase "$suite" "$tmp" "$mirror" > "$tmp.log" 2>&1 \
    || die "debootstrap $suite (log: $tmp.log): $(tail -3 "$tmp.log")"
  rm -f "$tmp.log"
  printf 'path-exclude=/usr/share/%s/*\n' doc man info locale lintian \
    > "$tmp/etc/dpkg/dpkg.cfg.d/01-qd-nodoc"
  [ -e "$tmp/etc/resolv.conf" ] || touch "$tmp/etc/resolv.conf"
}

# chroot_run DIR [SOURCE:TARGET[:ro]]... -- COMMAND...: runs COMMAND chrooted in DIR with /proc,
# a tmpfs on /tmp, the host's DNS set-up and the given bind mounts, in a clean environment.
chroot_run() {
  local dir="$1"
  shift
  local binds=()
  while [ "$1" != "--" ]; do binds+=("$1"); shift; done
  shift
  unshare --mount --propagation private bash -c '
    set -e; dir="$1"; shift
    mount -t proc proc "$dir/proc"
    mount -t tmpfs tmpfs "$dir/tmp"
    mount --bind -o ro /etc/resolv.conf "$dir/etc/resolv.conf"
    while [ "$1" != "--" ]; do
      IFS=: read -r src dst mode <<<"$1"; shift
      mount --bind "$src" "$dir$dst"
      [ "$mode" != ro ] || mount -o remount,bind,ro "$dir$dst"
    done
    shift; exec chroot "$dir" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
      LC_ALL=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"' \
    sh "$dir" "${binds[@]}" -- "$@"
}

# chroot_install DIR PACKAGES...: apt-get install --no-install-recommends in the chroot DIR (after
# the caller's apt-get update), then drops apt's caches and lists.
chroot_install() {
  local dir="$1"
  shift
  chroot_run "$dir" -- apt-get install -y -q --no-install-recommends "$@" > "$dir.log" 2>&1 \
    || die "apt-get install in $dir (log: $dir.log): $(tail -5 "$dir.log")"
  chroot_run "$dir" -- apt-get clean
  rm -rf "$dir"/var/lib/apt/lists/* "$dir"/var/cache/apt/*.bin "$dir.log"
}

# chroot_seal DIR SPEC: marks DIR.tmp complete for SPEC and renames it DIR.
chroot_seal() {
  echo "$2" > "$1.tmp/.qd-complete"
  mv "$1.tmp" "$1"
}
