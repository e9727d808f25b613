#!/usr/bin/env bash
# Times the README's quick start as a newcomer meets it: a fresh clone of this
# repository's HEAD on a fresh Debian 12 (a copy of a debootstrap'd bookworm,
# made once with `debootstrap bookworm ROOTFS http://deb.debian.org/debian`),
# as root in a chroot, apt included. Needs root and the Debian archive.
#   scripts/time_quick_start.sh ROOTFS LOGDIR [demo|both]
# Writes LOGDIR/demo.log (and test.log), each ending with a line
# `TIMING <command> wall S s user S s sys S s`, and LOGDIR/load.txt (uptime
# before and after each: the figures hold only for a machine otherwise idle).
set -euo pipefail
rootfs=$(realpath "$1") logs=$(realpath -m "$2") which=${3:-demo}
repo=$(cd "$(dirname "$0")/.." && pwd)
run=$(mktemp -d /tmp/quick_start.XXXXXX)
cleanup() {  # never rm a tree that still has the host's /dev mounted in it
  umount -R "$run/dev" "$run/sys" "$run/proc" 2>/dev/null || umount -lR "$run/dev" "$run/sys" "$run/proc" 2>/dev/null || true
  if grep -q " $run/" /proc/mounts; then echo "time_quick_start: $run still has mounts; not removed" >&2; else rm -rf "$run"; fi
}
trap cleanup EXIT
cp -a "$rootfs/." "$run/"
printf '%s\n' "deb http://deb.debian.org/debian bookworm main" \
  "deb http://deb.debian.org/debian bookworm-updates main" \
  "deb http://deb.debian.org/debian-security bookworm-security main" >"$run/etc/apt/sources.list"
cp /etc/resolv.conf "$run/etc/resolv.conf"
# A machine behind an intercepting proxy trusts its CA through NODE_EXTRA_CA_CERTS;
# the chroot gets the same trust, so npm reaches the registry as the host does.
extra_ca=
if [ -n "${NODE_EXTRA_CA_CERTS:-}" ] && [ -f "$NODE_EXTRA_CA_CERTS" ]; then
  cp "$NODE_EXTRA_CA_CERTS" "$run/root/extra-ca.pem" && extra_ca="NODE_EXTRA_CA_CERTS=/root/extra-ca.pem"
fi
mount -t proc proc "$run/proc"
mount --rbind /dev "$run/dev"
mount -t sysfs sys "$run/sys"
git clone -q "$repo" "$run/root/tumble"
mkdir -p "$logs"
time_in_chroot() {  # NAME: times ./scripts/NAME.sh in the clone
  echo "before $1: $(uptime)" >>"$logs/load.txt"
  local status=0
  chroot "$run" /bin/bash -c "cd /root/tumble && export $extra_ca HOME=/root LANG=C.UTF-8 PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    && TIMEFORMAT='TIMING $1 wall %R s user %U s sys %S s' && time ./scripts/$1.sh" >"$logs/$1.log" 2>&1 || status=$?
  echo "after $1: $(uptime)" >>"$logs/load.txt"
  echo "$1 exit status $status" | tee -a "$logs/$1.log"
  grep '^TIMING' "$logs/$1.log"
  return "$status"
}
time_in_chroot demo
[ "$which" = both ] && time_in_chroot test
exit 0
