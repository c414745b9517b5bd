# The c-wasm binding (issue 34, point 2): the C engine's own files (generated/c/cbf.h, cbf_tools.h,
# cbf_tool.c, cbf_testee.c), unchanged, built for wasm32-wasi with clang 14, wasm-ld (lld),
# wasi-libc and the wasm32 builtins (libclang-rt-14-dev-wasm32), which .ci/setup-debian.sh installs.
#   build/wasm/cbf-c.wasm        the WASI command cbf-c (a release artefact: `make dist` copies it)
#   build/wasm/cbf_testee.wasm   the conformance testee, which bindings.yaml runs under node
# node runs both with node:wasi, no npm package (generator/cbfgen/emit/c/wasm/wasi_run.mjs).
# Targets:
#   wasm-build   both modules (part of `make conformance`)

WASM_OUT := build/wasm
WASM_CC ?= clang
# The same strict warnings as every other C build; -O2 as native cbf-c. No exceptions, no
# threads, no signals: the engine needs none (a new need fails the build here, not at run time).
WASM_FLAGS := --target=wasm32-wasi --sysroot=/usr $(C_STRICT) -O2 -Wl,--strip-all -Wl,-z,stack-size=1048576
WASM_RUN := generator/cbfgen/emit/c/wasm/wasi_run.mjs

CONFORMANCE_BUILD += wasm-build
DIST_EXTRA += $(WASM_OUT)/cbf-c.wasm
.PHONY: wasm-build

$(WASM_OUT)/.dir:
	@mkdir -p $(WASM_OUT)
	@touch $@

$(WASM_OUT)/cbf-c.wasm: $(C_HDR) $(C_TOOLS_HDR) $(C_GEN)/cbf_tool.c mk/wasm.mk | $(WASM_OUT)/.dir
	$(WASM_CC) $(WASM_FLAGS) -o $@ $(C_GEN)/cbf_tool.c -lm

$(WASM_OUT)/cbf_testee.wasm: $(C_HDR) $(C_TOOLS_HDR) $(C_GEN)/cbf_testee.c mk/wasm.mk | $(WASM_OUT)/.dir
	$(WASM_CC) $(WASM_FLAGS) -o $@ $(C_GEN)/cbf_testee.c -lm

wasm-build: c-deps $(WASM_OUT)/cbf-c.wasm $(WASM_OUT)/cbf_testee.wasm  ## build cbf-c.wasm and the c-wasm testee (wasm32-wasi) into build/wasm

# `make bench` times cbf-c.wasm against native cbf-c (bench/wasm_rows.py).
bench: wasm-build $(C_OUT)/cbf-c
