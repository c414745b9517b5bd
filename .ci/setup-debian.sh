#!/usr/bin/env bash
# Install what the project needs and is missing, on Debian or Ubuntu (apt-get);
# anywhere else, stop at once and say what is missing. Idempotent, non-interactive,
# safe without stdin. Used by the Makefile fragments (c-deps, docs-check) and so by CI
# through `make test`. A tool counts as present when its command is on PATH (the
# version checks are the README's "Prerequisites"), so toolchains installed outside
# apt (Go in /usr/local/go, say) are used as they are.
#   python3 (>= 3.11)            the generator, the Python codec, the tests
#   node + npm (>= 20)           kaitai-struct-compiler 0.11 and its JavaScript runtime
#   go (>= 1.23)                 the Kaitai Go parser's testee (Debian 12's golang-go is 1.19:
#                                then install Go from go.dev; the script says so)
#   javac + mvn (JDK >= 11)      the Kaitai Java parser: its Maven package, testee and consumer test
#   gcc, g++, clang, libclang-rt-14-dev   the C binding, libFuzzer and sanitizers
#   lld (wasm-ld), wasi-libc, libclang-rt-14-dev-wasm32   the c-wasm binding: the C engine for wasm32-wasi
#   graphviz                     Kaitai's graphviz diagram in the docs
#   chromium, pdftotext          only with CBF_WANT_CHROMIUM=1: the headless browser of
#                                `make docs-check` and poppler-utils, whose pdftotext -bbox
#                                measures the printed PDF's pages (no page left mostly blank)
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
# command -> Debian package
declare -A pkg_of=(
  [python3]=python3 [node]=nodejs [npm]=npm [go]=golang-go [javac]=default-jdk-headless [mvn]=maven
  [gcc]=gcc [g++]=g++ [make]=make [git]=git [clang]=clang [wasm-ld]=lld [dot]=graphviz
)
order=(python3 node npm go javac mvn gcc g++ make git clang wasm-ld dot)
[ "${CBF_WANT_CHROMIUM:-0}" = 1 ] && { pkg_of[chromium]=chromium; pkg_of[pdftotext]=poppler-utils; order+=(chromium pdftotext); }
missing=()
for cmd in "${order[@]}"; do
  command -v "$cmd" >/dev/null 2>&1 || missing+=("${pkg_of[$cmd]}")
done
# libFuzzer and the sanitizer runtimes are a library, not a command.
if command -v dpkg >/dev/null 2>&1 && ! dpkg -s libclang-rt-14-dev >/dev/null 2>&1 \
   && ! compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" >/dev/null; then
  missing+=(libclang-rt-14-dev)
fi
# The c-wasm binding's C library and compiler builtins for wasm32-wasi (libraries too).
if command -v dpkg >/dev/null 2>&1; then
  [ -e /usr/include/wasm32-wasi/stdio.h ] || dpkg -s wasi-libc >/dev/null 2>&1 || missing+=(wasi-libc)
  compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/wasi/libclang_rt.builtins-wasm32.a" >/dev/null \
    || dpkg -s libclang-rt-14-dev-wasm32 >/dev/null 2>&1 || missing+=(libclang-rt-14-dev-wasm32)
fi
if [ ${#missing[@]} -eq 0 ]; then
  goversion=$(go env GOVERSION 2>/dev/null || echo go0)
  if ! printf '%s\n' go1.23 "$goversion" | sort -V -C; then
    echo "setup: $goversion is older than go1.23, which the Kaitai Go runtime needs (README 'Prerequisites')" >&2
    exit 1
  fi
  exit 0
fi
if ! command -v apt-get >/dev/null 2>&1; then
  echo "setup: missing ${missing[*]} (Debian package names); this script installs only on Debian or Ubuntu: install them, see README 'Prerequisites'" >&2
  exit 1
fi
if [ "$(id -u)" != 0 ]; then
  sudo=sudo
else
  sudo=
fi
echo "setup-debian: installing ${missing[*]}"
$sudo apt-get update -qq </dev/null
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null >/dev/null
