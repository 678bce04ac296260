#!/usr/bin/env bash
# test-setup/as-new-user.sh [PACKAGE ...] - runs ./antw test on a fresh clone of this repository as a user without
# root, on a machine where PACKAGE ... (default: socat mbpoll xvfb xauth) look uninstalled, to check that the tests
# that need them are skipped, each naming what is missing, and nothing fails. Needs root (to make the user and a
# private mount namespace); the machine itself is left as it is: inside the namespace, an overlay hides the
# packages' programs from /usr/bin and the dpkg status is a copy without them.
set -euo pipefail
[ "$(id -u)" -eq 0 ] || { echo "as-new-user.sh: run it as root (it makes a user and a mount namespace)" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
packages=("$@")
[ $# -gt 0 ] || packages=(socat mbpoll xvfb xauth)
command=${RWE_NEW_USER_COMMAND:-./antw test}   # what the user runs in the clone
user=rwe-newcomer
id "$user" >/dev/null 2>&1 || useradd -m -s /bin/bash "$user"
home=$(getent passwd "$user" | cut -d: -f6)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -rf "$home/clone"
git clone -q "$here" "$home/clone"
chown -R "$user:" "$home/clone"
mkdir -p "$work/up" "$work/work"
for package in "${packages[@]}"; do
  dpkg -L "$package" 2>/dev/null | grep '^/usr/bin/' | while read -r program; do
    mknod "$work/up/$(basename "$program")" c 0 0   # an overlay whiteout: the program is not there
  done
done
python3 - "$work/status" "${packages[@]}" <<'PY'
import re, sys
out, hidden = sys.argv[1], set(sys.argv[2:])
stanzas = open('/var/lib/dpkg/status').read().split('\n\n')
keep = [s for s in stanzas if not (m := re.match(r'Package: (\S+)\n', s)) or m.group(1) not in hidden]
open(out, 'w').write('\n\n'.join(keep))
PY
chmod 644 "$work/status"
unshare -m bash -c "
  mount -t overlay overlay -o lowerdir=/usr/bin,upperdir='$work/up',workdir='$work/work' /usr/bin
  mount --bind '$work/status' /var/lib/dpkg/status
  cd '$home/clone' && su '$user' -c 'env -u DISPLAY $command'
"
