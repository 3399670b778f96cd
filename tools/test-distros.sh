#!/usr/bin/env bash
# Proves the README's two commands on the other Debian releases, as a new user runs them: for
# each release (default: trixie = Debian 13, sid = Debian unstable),
#   1. makes a fresh minimal root with debootstrap --variant=minbase in
#      $LIGHTSHAFTS_DISTROS_ROOT/<release> (a root left by an earlier run is removed first);
#   2. copies this checkout into it as /root/LightShafts (the files git tracks, and the
#      untracked ones it does not ignore: in CI, a clean clone);
#   3. runs in it, with chroot, as root: tools/quickstart.sh, then tools/test.sh, then
#      tools/test-headless.sh (EGL and OSMesa through VTK's run-time choice where the
#      release's VTK has it, VTK 9.4 and later; it says when the release has no headless route);
#   4. prints one line per release, with what it has (VTK, ParaView, PyVista, Python) and the
#      suites' counts, then "N passed, N failed"; the exit status is non-zero when any failed.
# The releases run side by side (their downloads and installs overlap), each with its own X
# display numbers (LIGHTSHAFTS_XVFB_SERVERNUM: 110 for the first, 120 for the second, ...; the
# machine's own lane keeps 99).
#
#   tools/test-distros.sh [trixie] [sid]
#
# Needs root (debootstrap, chroot, mounts) and about 6 GB per release; debootstrap is
# apt-installed when missing. Logs: $LIGHTSHAFTS_DISTROS_ROOT/<release>.log (kept, as is the
# root, until the next run). The .debs apt downloads are kept in
# $LIGHTSHAFTS_DISTROS_ROOT/apt-cache/<release> for the next run (the roots start empty
# regardless). The Debian mirror here may serve a release whose Release file is past its date:
# the roots' apt is told to accept it (Acquire::Check-Valid-Until "false"), a fact of the
# mirror, not of the project.
#
# Environment: LIGHTSHAFTS_DISTROS_ROOT (default /opt/lightshafts/distros),
# LIGHTSHAFTS_DEBIAN_MIRROR (default http://deb.debian.org/debian),
# LIGHTSHAFTS_DISTRO_TIMEOUT (seconds per step, default 3600), LIGHTSHAFTS_DISTROS_PYTEST_MARK
# (a pytest -m expression for tools/test.sh's Python tests, default none: all of them; CI gives
# "not sweep", conftest.py).
set -euo pipefail
cd "$(dirname "$0")/.."
checkout=$PWD

distros_root=${LIGHTSHAFTS_DISTROS_ROOT:-/opt/lightshafts/distros}
mirror=${LIGHTSHAFTS_DEBIAN_MIRROR:-http://deb.debian.org/debian}
timeout_s=${LIGHTSHAFTS_DISTRO_TIMEOUT:-3600}
pytest_mark=${LIGHTSHAFTS_DISTROS_PYTEST_MARK:-}
releases=("$@")
[ ${#releases[@]} -gt 0 ] || releases=(trixie sid)

if [ "$(id -u)" -ne 0 ]; then
  echo "tools/test-distros.sh needs root (debootstrap, chroot, mounts): run it with sudo" >&2
  exit 2
fi
if ! command -v debootstrap > /dev/null; then
  # (The project's apt lock: tools/quickstart.sh may be installing beside this, as in CI.)
  echo "== apt-get install debootstrap"
  flock /var/lock/lightshafts-apt.lock sh -c 'export DEBIAN_FRONTEND=noninteractive
    apt-get -o DPkg::Lock::Timeout=600 install -y -qq debootstrap > /dev/null 2>&1 ||
    { apt-get -o DPkg::Lock::Timeout=600 update -qq &&
      apt-get -o DPkg::Lock::Timeout=600 install -y -qq debootstrap > /dev/null; }'
fi
mkdir -p "$distros_root"

# Unmounts everything mounted under $1 (deepest first).
unmount_under() {
  local root=$1 mountpoint
  for mountpoint in $(awk -v r="$root/" 'index($2, r) == 1 { print $2 }' /proc/mounts |
    sort -r); do
    umount -R "$mountpoint" 2> /dev/null || umount -l "$mountpoint" 2> /dev/null || true
  done
}

# Kills the processes running inside the root $1 (an Xvfb a failed run left, say).
kill_inside() {
  local root=$1 proc
  for proc in /proc/[0-9]*; do
    if [ "$(readlink "$proc/root" 2> /dev/null)" = "$root" ]; then
      kill -9 "${proc#/proc/}" 2> /dev/null || true
    fi
  done
}

# Makes the fresh root $2 of release $1.
make_root() {
  local release=$1 root=$2 cache=$3
  kill_inside "$root"
  unmount_under "$root"
  rm -rf "$root"
  mkdir -p "$cache"
  echo "== [$release] debootstrap --variant=minbase $release $root"
  debootstrap --variant=minbase "--cache-dir=$cache" "$release" "$root" "$mirror" \
    > "$root.debootstrap.log" 2>&1 || {
    tail -20 "$root.debootstrap.log" >&2
    echo "debootstrap failed ($root.debootstrap.log)" >&2
    return 1
  }
  echo 'Acquire::Check-Valid-Until "false";' > "$root/etc/apt/apt.conf.d/99lightshafts-mirror"
  cp -L /etc/resolv.conf "$root/etc/resolv.conf"
  # The checkout, as cloned: tracked files and untracked ones git does not ignore.
  mkdir -p "$root/root/LightShafts"
  git -C "$checkout" ls-files -z --cached --others --exclude-standard |
    (cd "$checkout" && xargs -0 tar -cf - --no-recursion) |
    tar -xf - -C "$root/root/LightShafts"
  mount -t proc proc "$root/proc"
  mount -t sysfs sysfs "$root/sys"
  mount --rbind /dev "$root/dev"
  mount --make-rslave "$root/dev"
  mkdir -p "$root/var/cache/apt/archives"
  mount --bind "$cache" "$root/var/cache/apt/archives"
}

# Runs $3... inside the root $1 as a new user's root shell would, in /root/LightShafts, with X
# display numbers from $2 on.
inside() {
  local root=$1 servernum=$2
  shift 2
  chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LIGHTSHAFTS_XVFB_SERVERNUM="$servernum" \
    bash -c 'cd /root/LightShafts && "$@"' bash "$@"
}

# One release: its root, the README's two commands and the headless script; prints its line.
# $2: its first X display number.
test_release() {
  local release=$1 servernum=$2 root=$distros_root/$1 log=$distros_root/$1.log
  local cache=$distros_root/apt-cache/$1 status=0 start steps="" step_start outcome
  start=$(date +%s)
  : > "$log"
  if ! make_root "$release" "$root" "$cache" >> "$log" 2>&1; then
    echo "$release: FAILED: its root could not be made ($log)"
    return 1
  fi
  for step in quickstart.sh test.sh test-headless.sh; do
    step_start=$(date +%s)
    local args=()
    [ "$step" = test.sh ] && [ -n "$pytest_mark" ] && args=(-m "$pytest_mark")
    echo "== [$release] tools/$step ${args[*]}" >> "$log"
    outcome=0
    timeout "$timeout_s" bash -c "$(declare -f inside); inside \"\$@\"" bash "$root" \
      "$servernum" "tools/$step" "${args[@]}" >> "$log" 2>&1 || outcome=$?
    steps+="${steps:+, }$step $(($(date +%s) - step_start)) s"
    if [ "$outcome" -ne 0 ]; then
      status=1
      steps+=" (FAILED, status $outcome)"
      [ "$step" = quickstart.sh ] && break
    fi
  done
  kill_inside "$root"
  unmount_under "$root"

  # What the release has, and what its suites counted.
  local versions ctest pytest headless
  versions=$(chroot "$root" dpkg-query -W -f='${Package} ${Version}\n' libvtk9-dev paraview \
    python3-pyvista python3 2> /dev/null | awk '
      { sub(/[+~-].*/, "", $2); v[$1] = $2 }
      END {
        printf "VTK %s, ParaView %s, PyVista %s, Python %s", v["libvtk9-dev"], v["paraview"],
          ("python3-pyvista" in v) ? v["python3-pyvista"] : "none", v["python3"]
      }')
  ctest=$(grep -E "^[0-9]+% tests passed" "$log" | head -1 |
    sed -E 's/[0-9]+% tests passed, ([0-9]+) tests failed out of ([0-9]+)/ctest \1 failed of \2/')
  pytest=$(grep -E "^=* ?[0-9]+ (passed|failed).* in [0-9.]+s" "$log" | head -1 |
    sed -E 's/^=+ //; s/ in [0-9.]+s.*//')
  headless=$(sed -n '/== headless backends/,$p' "$log" | grep -E '^(egl|osmesa):' |
    sed -E 's/ \(runtime, [0-9]+ s\)//; s/: this system.s Mesa has no OSMesa.*/ (no OSMesa in Mesa)/' |
    tr '\n' ';' | sed 's/;$//; s/;/; /g')
  [ -n "$headless" ] || headless=$(grep -q "no headless route" "$log" &&
    echo "no route (VTK ${versions#VTK }: its build is X only)" | sed -E 's/, .*:/:/')
  local verdict=passed
  [ "$status" -eq 0 ] || verdict=FAILED
  echo "$release ($versions): $verdict in $((($(date +%s) - start) / 60)) min:" \
    "${ctest:-ctest did not run}; pytest ${pytest:-did not run}; headless: ${headless:-none}" \
    "[$steps] ($log)"
  return "$status"
}

passed=0
failed=0
lines=()
pids=()
for i in "${!releases[@]}"; do
  # (errexit off: a background subshell keeps it, and test_release's last greps may match
  # nothing, as a command substitution, which drops it, allowed.)
  (
    set +e
    test_release "${releases[$i]}" $((110 + 10 * i))
  ) > "$distros_root/${releases[$i]}.line" &
  pids+=($!)
done
for i in "${!releases[@]}"; do
  if wait "${pids[$i]}"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
  line=$(cat "$distros_root/${releases[$i]}.line")
  [ -n "$line" ] || line="${releases[$i]}: FAILED: it printed no result ($distros_root/${releases[$i]}.log)"
  echo "$line"
  lines+=("$line")
done
echo "== Debian releases in fresh roots"
printf '%s\n' "${lines[@]}"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
