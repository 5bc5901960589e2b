#!/usr/bin/env bash
# Runs one of the README's set-up commands on a true fresh machine: a minimal Debian 12 (mmdebstrap's
# minbase: the required packages and apt, nothing else) built from Debian's registry, holding a copy
# of this working tree (tracked files and untracked ones git does not ignore). Run it as root before
# a release: a reused machine keeps whatever was once installed by hand, and hides a missing package.
#   bash scripts/fresh_machine.sh [demo|test] [FOLDER]     (default: demo in /var/tmp/fractograph-fresh)
# The chroot shares this machine's network; npm inside it gets this machine's npm configuration and
# CA certificates, since a minimal Debian has neither. Its log is FOLDER/run.log.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
COMMAND=${1:-demo}
WORK=${2:-/var/tmp/fractograph-fresh}
CHROOT=$WORK/debian12

say() { printf '\033[1m==> %s\033[0m\n' "$*"; }
[ "$(id -u)" -eq 0 ] || { echo "run as root (mmdebstrap and chroot)" >&2; exit 2; }
command -v mmdebstrap >/dev/null || { apt-get update -qq; apt-get install -y -qq --no-install-recommends mmdebstrap >/dev/null; }

rm -rf "$CHROOT"
mkdir -p "$WORK"
say "making a minimal Debian 12 in $CHROOT"
mmdebstrap --variant=minbase --quiet bookworm "$CHROOT" \
  "deb http://deb.debian.org/debian bookworm main" \
  "deb http://deb.debian.org/debian bookworm-updates main" \
  "deb http://deb.debian.org/debian-security bookworm-security main"

say "copying the working tree to /root/fractograph"
mkdir -p "$CHROOT/root/fractograph"
(cd "$ROOT" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -cf -) | tar -C "$CHROOT/root/fractograph" -xf -

cp /etc/resolv.conf "$CHROOT/etc/resolv.conf"
[ -f /etc/npmrc ] && cp /etc/npmrc "$CHROOT/etc/npmrc"
[ -f "$HOME/.npmrc" ] && cp "$HOME/.npmrc" "$CHROOT/root/.npmrc"
# This machine's certificates under a name of their own: installing ca-certificates in the chroot
# rewrites its bundle, and a registry reached through a proxy may need this machine's.
[ -f /etc/ssl/certs/ca-certificates.crt ] && cp /etc/ssl/certs/ca-certificates.crt "$CHROOT/etc/host-ca-certificates.crt"

say "running 'bash scripts/fractograph.sh $COMMAND' inside it (log: $WORK/run.log)"
start=$SECONDS
set +e
# A mount namespace of its own: /proc and /dev go away with it, whatever happens inside.
unshare --mount --fork sh -c '
  mount -t proc proc "$1/proc" && mount --rbind /dev "$1/dev" && mount -t sysfs sys "$1/sys" &&
  chroot "$1" /usr/bin/env -i HOME=/root TERM=dumb npm_config_cafile=/etc/host-ca-certificates.crt PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    bash -c "cd /root/fractograph && bash scripts/fractograph.sh $2"' sh "$CHROOT" "$COMMAND" 2>&1 | tee "$WORK/run.log"
rc=${PIPESTATUS[0]}
set -e
say "'$COMMAND' in a minimal Debian 12: exit $rc after $(((SECONDS - start) / 60)) min $(((SECONDS - start) % 60)) s"
exit "$rc"
