#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# How long the Makefile's package install (`make deps-evaluate`, the `deps` target's command) takes on
# a fresh Debian 12 machine, which `make evaluate`'s time budget includes. A machine that already has
# the packages cannot show it, so the install runs in a chroot:
#  1. a minimal bookworm root (mmdebstrap, variant minbase), from this machine's own mirror and apt
#     settings, with what a fresh machine already has (BASE_PACKAGES: g++, make, cmake, git, python3);
#  2. for each run, a copy of that root with an empty apt cache and no package lists (a fresh
#     machine's state), in which the Makefile's command runs as it is, timed: `apt-get update` and
#     the install, the latter split into download and unpack/configure (dpkg's first log line);
#  3. a table: packages installed, bytes downloaded, the installed size, and the times.
# Network speed varies from run to run, and a mirror's cache may serve a second run faster.
# Needs root, and Debian's mirror (mmdebstrap is installed if missing).
#
#   benchmark/package_install_time.sh [-n RUNS] [PACKAGE...]
#     default packages: EVALUATE_PACKAGES from the Makefile; default RUNS: 2
#   environment: PKGROOT (default /tmp/pkgroot, removed at the end),
#                BASE_PACKAGES (default "g++ make cmake git python3 ca-certificates")
set -eu
# The whole script is read before it runs (one block): it goes on even if the file changes meanwhile.
{
runs=2
if [ "${1:-}" = "-n" ]; then runs=$2; shift 2; fi
repo=$(cd "$(dirname "$0")/.." && pwd)
root=${PKGROOT:-/tmp/pkgroot}
base_packages=${BASE_PACKAGES:-g++ make cmake git python3 ca-certificates}

if [ $# -gt 0 ]; then
  packages=$*
else
  # The assignment with its continuation lines, without running make.
  packages=$(awk '/^EVALUATE_PACKAGES[ \t]*=/ { on = 1; sub(/^[^=]*=/, "") }
                  on { line = $0; more = sub(/\\[ \t]*$/, "", line); printf "%s ", line; if (!more) exit }' \
             "$repo/Makefile" | tr -s ' \t' '  ')
fi
[ -n "$(echo "$packages" | tr -d ' ')" ] || { echo "no packages to install" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "needs root (chroot, mounts)" >&2; exit 1; }

if ! command -v mmdebstrap > /dev/null; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends mmdebstrap
fi

# One run at a time: a second would delete the first one's root.
exec 9> "$root.lock"
flock -n 9 || { echo "another run uses $root" >&2; exit 1; }
rm -rf "$root"
mkdir -p "$root"
trap 'rm -rf "$root" "$root.lock"' EXIT
trap 'exit 130' INT TERM

# The same mirror as this machine's; its sources (one-line or deb822) go in on standard input.
sources=$root/sources
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
  [ -s "$f" ] && { grep -v '^[[:space:]]*#' "$f"; echo; }
done > "$sources" 2> /dev/null || true
[ -s "$sources" ] || { echo "no apt sources on this machine" >&2; exit 1; }

echo "load before: $(uptime)"
echo "packages: $packages"
echo "building the base root (minbase + $base_packages) ..."
t=$(date +%s)
mmdebstrap --quiet --variant=minbase --include="$(echo "$base_packages" | tr -s ' ' ',')" \
  bookworm "$root/base" - < "$sources" > "$root/mmdebstrap.log" 2>&1 \
  || { cat "$root/mmdebstrap.log" >&2; exit 1; }
echo "base root: $(( $(date +%s) - t )) s, $(du -sxm "$root/base" | cut -f1) MiB"
# This machine's apt and dpkg settings are a fresh machine's, and they change the times: apt's (no
# translations, compressed lists, no AppStream metadata) what `apt-get update` fetches, dpkg's
# (Debian's container images have force-unsafe-io: no fsync per unpacked file) the unpacking, several
# times slower without.
cp -a /etc/apt/apt.conf.d/. "$root/base/etc/apt/apt.conf.d/"
if [ -d /etc/dpkg/dpkg.cfg.d ]; then
  mkdir -p "$root/base/etc/dpkg/dpkg.cfg.d" && cp -a /etc/dpkg/dpkg.cfg.d/. "$root/base/etc/dpkg/dpkg.cfg.d/"
fi
[ -f /usr/sbin/policy-rc.d ] && cp -a /usr/sbin/policy-rc.d "$root/base/usr/sbin/"
cp /etc/resolv.conf "$root/base/etc/resolv.conf" 2> /dev/null || true

# Inside the chroot: the Makefile's `deps` command (only what is missing), with timestamps between
# its two steps, and the processor time it took (`times`: the shell's, then its children's), which
# another load on the machine stretches far less than the wall time.
cat > "$root/base/root/timed.sh" << 'EOF'
set -e
missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' $p 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
echo "$missing" > /root/missing
date +%s.%N > /root/t0
apt-get update -qq
date +%s.%N > /root/t1
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
date +%s.%N > /root/t2
times > /root/times
EOF

# A dpkg.log time in seconds since the epoch (the chroot's time zone is dpkg's); $2 when none.
stamp() { if [ -n "$1" ]; then chroot "$r" date -d "$1" +%s; else echo "$2"; fi; }
table=$root/table.md
echo "| run | packages | download MiB | installed MiB | lists MiB | update s | download s | unpack s | configure s | total s | cpu s | load before |" > "$table"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |" >> "$table"
i=1
while [ "$i" -le "$runs" ]; do
  r=$root/run$i
  cp -a "$root/base" "$r"
  chroot "$r" apt-get clean
  rm -rf "$r"/var/lib/apt/lists/*
  mkdir -p "$r/var/lib/apt/lists/partial"
  : > "$r/var/log/dpkg.log"
  before=$(du -sxk "$r" | cut -f1)
  load=$(uptime | sed 's/.*load average: //; s/,.*//')
  echo "run $i: installing ..."
  # A private mount namespace: /proc and /dev go away with it, whatever happens.
  if ! unshare --mount --propagation private sh -c '
        mount -t proc proc "$1/proc" && mount --bind /dev "$1/dev" && mount --bind /dev/pts "$1/dev/pts" &&
        chroot "$1" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
          PACKAGES="$2" sh /root/timed.sh' sh "$r" "$packages" > "$root/run$i.log" 2>&1; then
    cat "$root/run$i.log" >&2; echo "run $i failed" >&2; exit 1
  fi
  after=$(du -sxk "$r" | cut -f1)
  t0=$(cat "$r/root/t0"); t1=$(cat "$r/root/t1"); t2=$(cat "$r/root/t2")
  # dpkg starts only once apt has every archive: its first log line ends the download, its first
  # `configure` line the unpacking (1 s steps).
  tu=$(stamp "$(head -n 1 "$r/var/log/dpkg.log" | cut -c1-19)" "$t2")
  tc=$(stamp "$(grep -m 1 ' configure ' "$r/var/log/dpkg.log" | cut -c1-19)" "$t2")
  cpu=$(sed -n 2p "$r/root/times" | tr 'ms' '  ' | awk '{ print $1 * 60 + $2 + $3 * 60 + $4 }')
  count=$(find "$r/var/cache/apt/archives" -maxdepth 1 -name "*.deb" | wc -l)
  bytes=$(cat "$r"/var/cache/apt/archives/*.deb 2> /dev/null | wc -c)
  lists=$(du -sxk "$r/var/lib/apt/lists" | cut -f1)
  archives=$(du -sxk "$r/var/cache/apt/archives" | cut -f1)
  echo "$i $count $bytes $before $after $lists $t0 $t1 $tu $t2 $load $archives $tc $cpu" | awk '{
    printf "| %d | %d | %.1f | %.0f | %.1f | %.1f | %.0f | %.0f | %.0f | %.1f | %.1f | %s |\n",
      $1, $2, $3 / 1048576, ($5 - $4 - $6 - $12) / 1024, $6 / 1024, $8 - $7, $9 - $8, $13 - $9,
      $10 - $13, $10 - $7, $14, $11 }' >> "$table"
  echo "  missing:$(cat "$r/root/missing")"
  tail -n 1 "$table"
  rm -rf "$r"
  i=$((i + 1))
done

echo
echo "Package install on a fresh Debian 12 root ($(nproc) cores), the Makefile's command:"
cat "$table"
echo "update s: apt-get update; download s: from the install's start to dpkg's first log line; unpack s: to"
echo "dpkg's first configure; configure s: to the install's end (postinst scripts, triggers); 1 s steps."
echo "cpu s: user + system time of apt-get update and install with their children (on an idle machine"
echo "the wall time of a mostly serial install comes near it, plus the download)."
echo "load after: $(uptime)"
exit
}
