# Spec fuzzing as a standing campaign (issue 36, point 2): tests/spec_fuzz.py.
#   fuzz-spec   SPEC_FUZZ_COUNT (default 1,000) grammar-aware mutants of spec/cbf.yaml from
#               SPEC_FUZZ_SEED (default: the clock, printed), SPEC_FUZZ_JOBS at a time, nice'd:
#               each refused by `cbfgen --check-spec` with a line, or generated, compiled under
#               the strict C flags, imported, and run over the golden files by cbf and cbf-c with
#               identical output. One line a mutant, then the counts by outcome (accepted,
#               refused, crash:*, broken:*); a crashing or broken mutant's spec is kept in
#               build/spec-fuzz/ and the target fails.
# `make test` runs a fixed, derandomised sample and every class issue 36 found
# (tests/test_spec_fuzz.py). The loader judges every mutant in the campaign's own process (what
# --check-spec runs; about 0.3 s a mutant); only accepted ones are built (generate, compile, two tools
# over the golden files: 5-6 CPU s), and one whose generated Python and C equal an earlier mutant's
# reuses its outcome (about half do): 1,000 mutants took 540 s on one core (seed 2026120605).
# A campaign's failing mutants again: python tests/spec_fuzz.py run --seed S --count N --index I ...
#   fuzz-spec-loader   the same mutants through the loader alone, in one process (about 1 s a mutant):
#               refused with a line, accepted, or a crash; the gate count of issue 36 point 1 in minutes.
SPEC_FUZZ_COUNT ?= 1000
SPEC_FUZZ_SEED ?= $(shell date +%s)
SPEC_FUZZ_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
.PHONY: fuzz-spec fuzz-spec-loader

fuzz-spec: venv  ## a long random campaign of mutated specs (SPEC_FUZZ_COUNT, SPEC_FUZZ_SEED)
	nice -n 10 $(PY) tests/spec_fuzz.py run --seed $(SPEC_FUZZ_SEED) --count $(SPEC_FUZZ_COUNT) \
	  --jobs $(SPEC_FUZZ_JOBS) --keep build/spec-fuzz

fuzz-spec-loader: venv  ## the campaign's mutants through the loader alone (SPEC_FUZZ_COUNT, SPEC_FUZZ_SEED)
	nice -n 10 $(PY) tests/spec_fuzz.py run --loader-only --seed $(SPEC_FUZZ_SEED) --count $(SPEC_FUZZ_COUNT) \
	  --keep build/spec-fuzz
