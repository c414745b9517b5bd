#!/usr/bin/env bash
# Install the Debian packages the project needs, only when missing.
# Idempotent, non-interactive, safe without stdin. Used by the Makefile
# fragments (c-deps, docs-check) and by CI through `make test`.
#   clang + libclang-rt-14-dev   libFuzzer and the sanitizer runtimes (C binding)
#   graphviz                     Kaitai's graphviz diagram in the docs (optional)
#   chromium                     only with CBF_WANT_CHROMIUM=1: headless browser of
#                                `make docs-check` (about 15 s to install on Debian 12)
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
want=(clang libclang-rt-14-dev graphviz)
[ "${CBF_WANT_CHROMIUM:-0}" = 1 ] && want+=(chromium)
missing=()
for pkg in "${want[@]}"; do
  dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
if [ "$(id -u)" != 0 ]; then
  sudo=sudo
else
  sudo=
fi
echo "setup-debian: installing ${missing[*]}"
$sudo apt-get update -qq </dev/null
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null >/dev/null
