# C binding (issue #5): generated/c/ (cbf.h, the tools' engine cbf_tools.h, testee, cbf-c tool, fuzz harness)
# built into build/c/. Targets:
#   c-build    the conformance testee (ASan/UBSan), the cbf-c tool, the fuzzer
#   c-check    strict builds: gcc and clang C99, g++ as C++, clang -Weverything
#   c-test     C conformance smoke test of the sanitizer testee (also in CI)
#   fuzz-c     libFuzzer for FUZZ_SECONDS (default 30) from the golden files
#   c-fuzz-ci  a fixed seed and a fixed number of runs from the golden files only, so that
#              `make test` is deterministic (part of `make test`; fuzz-c and fuzz-long explore)
# Needs gcc, g++, clang and libclang-rt-14-dev (libFuzzer, sanitizers):
# .ci/setup-debian.sh installs them when clang is missing.

C_GEN := generated/c
C_OUT := build/c
C_HDR := $(C_GEN)/cbf.h
C_TOOLS_HDR := $(C_GEN)/cbf_tools.h
C_CC ?= gcc
C_CLANG ?= clang
C_CXX ?= g++
# -Wswitch-enum: the engine switches over the registry's kinds (check kinds, field kinds) with no default,
# so a kind the registry gains and the C runtime lacks fails the build (issue #24).
C_WARN := -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wdouble-promotion -Wswitch-enum -Werror
C_STRICT := -std=c99 $(C_WARN)
# As C++ (the header's extern "C" and the implementation compile as C++ too).
# -Wdouble-promotion stays; only C99-only idioms are accepted.
C_CXX_STRICT := -x c++ -std=c++11 $(C_WARN)
# clang -Weverything, minus a short list:
#   -Wno-padded                  structs follow the spec's field order; padding is expected
#   -Wno-declaration-after-statement  C99 allows it (clang 14 does not flag it in C99, kept for newer clangs)
#   -Wno-unknown-warning-option  so the list works on clang versions without the last flag
C_EVERYTHING := -std=c99 -Weverything -Werror -Wno-padded -Wno-unknown-warning-option -Wno-declaration-after-statement
C_SAN := -g -O1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
C_FUZZ_FLAGS := -g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_SECONDS ?= 30
# Inputs (and golden seeds, such as the 65,535-record file) are cut to this
# length, so the fuzzer mutates at thousands of runs a second.
FUZZ_MAX_LEN ?= 16384
C_GOLDEN := $(wildcard conformance/golden/*.cbf)
C_SOURCES := $(C_HDR) $(C_TOOLS_HDR) $(C_GEN)/cbf_testee.c $(C_GEN)/cbf_tool.c $(C_GEN)/cbf_fuzz.c

# The C checks need no .venv: `make test` runs them while pip installs it (TEST_EARLY).
TEST_EARLY += c-check c-test c-fuzz-ci
CONFORMANCE_BUILD += c-build
.PHONY: c-deps c-build c-check c-test fuzz-c c-fuzz-ci

# clang, libFuzzer and the sanitizer runtimes come from Debian's packages.
c-deps:
	@.ci/setup-debian.sh

$(C_OUT)/.dir:
	@mkdir -p $(C_OUT)/obj $(C_OUT)/fuzz-corpus
	@touch $@

# The conformance testee, with AddressSanitizer and UBSan (bindings.yaml runs it).
$(C_OUT)/cbf_testee: $(C_HDR) $(C_TOOLS_HDR) $(C_GEN)/cbf_testee.c | $(C_OUT)/.dir
	$(C_CC) $(C_STRICT) $(C_SAN) -o $@ $(C_GEN)/cbf_testee.c -lm

# The reference command-line tool.
$(C_OUT)/cbf-c: $(C_HDR) $(C_TOOLS_HDR) $(C_GEN)/cbf_tool.c | $(C_OUT)/.dir
	$(C_CC) $(C_STRICT) -O2 -o $@ $(C_GEN)/cbf_tool.c -lm

# The libFuzzer harness (clang only).
$(C_OUT)/cbf_fuzz: $(C_HDR) $(C_GEN)/cbf_fuzz.c | $(C_OUT)/.dir
	$(C_CLANG) -std=c99 $(C_WARN) $(C_FUZZ_FLAGS) -o $@ $(C_GEN)/cbf_fuzz.c -lm

c-build: c-deps $(C_OUT)/cbf_testee $(C_OUT)/cbf-c $(C_OUT)/cbf_fuzz  ## build the C testee, cbf-c and the fuzzer into build/c

# Every translation unit with every strict compiler; the header alone too.
$(C_OUT)/check.stamp: $(C_SOURCES) mk/c.mk | $(C_OUT)/.dir
	@printf '#include "cbf.h"\nint cbf_header_only(void);\nint cbf_header_only(void) { return CBF_COMMAND_COUNT; }\n' > $(C_OUT)/obj/header_only.c
	@set -e; for src in $(C_OUT)/obj/header_only.c $(C_GEN)/cbf_testee.c $(C_GEN)/cbf_tool.c $(C_GEN)/cbf_fuzz.c; do \
	  base=$$(basename $$src .c); \
	  echo "c-check: $$base: gcc, clang, g++ (C++), clang -Weverything"; \
	  $(C_CC) $(C_STRICT) -I$(C_GEN) -c $$src -o $(C_OUT)/obj/$$base.gcc.o; \
	  $(C_CLANG) $(C_STRICT) -I$(C_GEN) -c $$src -o $(C_OUT)/obj/$$base.clang.o; \
	  $(C_CXX) $(C_CXX_STRICT) -I$(C_GEN) -c $$src -o $(C_OUT)/obj/$$base.cxx.o; \
	  $(C_CLANG) $(C_EVERYTHING) -I$(C_GEN) -c $$src -o $(C_OUT)/obj/$$base.every.o; \
	done
	@touch $@

# The hand-written C (issue #24: runtime/, the engine in cbf.h; issue #33: tools/, the tools' engine in
# cbf_tools.h, cbf-c's command line and the testee), compiled from its own files: each generated file with
# each verbatim section (between its BEGIN/END markers) replaced by an #include of runtime/<file> or
# tools/<file> and its #line directives dropped, so that every diagnostic names the file a developer
# edits; the same strict compilers.
C_RUNTIME := generator/cbfgen/emit/c/runtime
C_TOOLS := generator/cbfgen/emit/c/tools
C_RUNTIME_FILES := $(wildcard $(C_RUNTIME)/*.c $(C_RUNTIME)/*.h $(C_TOOLS)/*.c $(C_TOOLS)/*.h)
C_LINT := $(C_OUT)/obj/lint
C_UNSECTION := awk '/^\/\* ==== BEGIN (runtime|tools)\// { f = $$4; sub(/^(runtime|tools)\//, "", f); sub(/:$$/, "", f); \
	  print "\#include \"" f "\""; skip = 1; n++; next } \
	  /^\/\* ==== END (runtime|tools)\// { skip = 0; next } \
	  /^\#line / { next } \
	  !skip { print } \
	  END { if (n == 0) { print "runtime-lint: no hand-written section in " FILENAME > "/dev/stderr"; exit 1 } }'
$(C_OUT)/runtime.stamp: $(C_SOURCES) $(C_RUNTIME_FILES) mk/c.mk | $(C_OUT)/.dir
	@mkdir -p $(C_LINT)
	@set -e; for f in cbf.h cbf_tools.h cbf_testee.c cbf_tool.c cbf_fuzz.c; do $(C_UNSECTION) $(C_GEN)/$$f > $(C_LINT)/$$f; done
	@printf '#define CBF_IMPLEMENTATION\n#include "cbf.h"\n' > $(C_LINT)/runtime_lint.c
	@echo "c-check: runtime/ and tools/ ($(notdir $(C_RUNTIME_FILES))): gcc, clang, g++ (C++), clang -Weverything"
	@set -e; inc="-I$(C_RUNTIME) -I$(C_TOOLS)"; for src in runtime_lint cbf_testee cbf_tool cbf_fuzz; do \
	  $(C_CC) $(C_STRICT) $$inc -c $(C_LINT)/$$src.c -o $(C_LINT)/$$src.gcc.o; \
	  $(C_CLANG) $(C_STRICT) $$inc -c $(C_LINT)/$$src.c -o $(C_LINT)/$$src.clang.o; \
	  $(C_CXX) $(C_CXX_STRICT) $$inc -c $(C_LINT)/$$src.c -o $(C_LINT)/$$src.cxx.o; \
	  $(C_CLANG) $(C_EVERYTHING) $$inc -c $(C_LINT)/$$src.c -o $(C_LINT)/$$src.every.o; \
	done
	@touch $@

c-check: c-deps $(C_OUT)/check.stamp $(C_OUT)/runtime.stamp  ## strict C builds (runtime/ and tools/ from their own files too): gcc, clang, g++ as C++, clang -Weverything

# A smoke run of the sanitizer testee on the golden files: every request is
# answered with one JSON line (the conformance runner does the judging).
c-test: c-build  ## run the sanitizer C testee over the golden files
	@set -e; n=0; for f in $(C_GOLDEN); do \
	  printf '{"op": "decode", "file": "%s"}\n{"op": "validate", "file": "%s", "profile": "default", "part_number": null, "cutters": null}\n' "$(CURDIR)/$$f" "$(CURDIR)/$$f"; n=$$((n+1)); \
	done > $(C_OUT)/smoke.jsonl; echo '{"op": "quit"}' >> $(C_OUT)/smoke.jsonl; \
	$(C_OUT)/cbf_testee < $(C_OUT)/smoke.jsonl > $(C_OUT)/smoke.out; \
	lines=$$(wc -l < $(C_OUT)/smoke.out); \
	if [ "$$lines" -ne $$((2*n)) ]; then echo "c-test: $$lines answers for $$((2*n)) requests" >&2; exit 1; fi; \
	echo "c-test: $$n golden file(s) decoded and validated under ASan/UBSan"

fuzz-c: c-build  ## run the C libFuzzer harness for FUZZ_SECONDS (default 30)
	@mkdir -p $(C_OUT)/fuzz-seeds
	@for f in $(C_GOLDEN); do cp -f $$f $(C_OUT)/fuzz-seeds/; done
	$(C_OUT)/cbf_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=$(C_OUT)/ -max_len=$(FUZZ_MAX_LEN) \
	  $(C_OUT)/fuzz-corpus $(C_OUT)/fuzz-seeds

# Deterministic: one process, -seed fixed, -runs fixed, a fresh corpus of the golden files
# alone (no corpus kept from earlier runs), so the same commit runs the same inputs.
FUZZ_CI_RUNS ?= 20000
c-fuzz-ci: c-build
	@rm -rf $(C_OUT)/fuzz-ci && mkdir -p $(C_OUT)/fuzz-ci/corpus $(C_OUT)/fuzz-ci/seeds
	@for f in $(C_GOLDEN); do cp -f $$f $(C_OUT)/fuzz-ci/seeds/; done
	$(C_OUT)/cbf_fuzz -seed=1 -runs=$(FUZZ_CI_RUNS) -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
	  -artifact_prefix=$(C_OUT)/ -max_len=$(FUZZ_MAX_LEN) $(C_OUT)/fuzz-ci/corpus $(C_OUT)/fuzz-ci/seeds

# Install the C binding for consumers outside this repository (issue #14):
#   $(PREFIX)/include/cbf.h, $(PREFIX)/bin/cbf-c, $(PREFIX)/lib/pkgconfig/cbf.pc
# Then `pkg-config --cflags cbf` finds the header (PKG_CONFIG_PATH=$(PREFIX)/lib/pkgconfig
# when PREFIX is not a system prefix). DESTDIR is honoured for staged installs.
PREFIX ?= /usr/local
.PHONY: install
install: $(C_OUT)/cbf-c  ## install cbf.h, cbf-c and cbf.pc under PREFIX (default /usr/local)
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 0644 $(C_HDR) $(DESTDIR)$(PREFIX)/include/cbf.h
	install -m 0755 $(C_OUT)/cbf-c $(DESTDIR)$(PREFIX)/bin/cbf-c
	sed 's|@PREFIX@|$(PREFIX)|' $(C_GEN)/cbf.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/cbf.pc
	@echo "installed cbf.h, cbf-c and cbf.pc under $(DESTDIR)$(PREFIX)"
