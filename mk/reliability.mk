# Reliability campaign (issue #7): conformance/reliability/README.md.
#   reliability        the full campaign: every valid golden file, 10,000 differential
#                      files; writes conformance/reliability.json, then the docs' table
#   reliability-quick  the CI part (distinct golden files up to 700 bytes, a seeded 4% of
#                      the Python codec's corruption and blind-spot mutants, 1,000 differential
#                      files); writes build/reliability/reliability.json
#   fuzz-long          libFuzzer on the C harness for FUZZ_LONG_RUNS executions (10 M),
#                      outside CI; the count goes into conformance/reliability.json
RELIABILITY_FILES ?= 10000
FUZZ_LONG_RUNS ?= 10000000
FUZZ_LONG_JOBS ?= 2
.PHONY: reliability reliability-quick fuzz-long test-long

# Random exploration, outside `make test` (which is derandomised, tests/conftest.py):
# the property tests with hypothesis' "long" profile, a new random seed each run.
# A failure it finds becomes an explicit @example regression test.
HYPOTHESIS_TESTS := $(shell grep -l '^from hypothesis' tests/*.py)
test-long: venv  ## property tests with random seeds and many examples (hypothesis "long" profile)
	HYPOTHESIS_PROFILE=long $(PY) -m pytest -p no:cacheprovider $(HYPOTHESIS_TESTS)

reliability: venv test-long  ## full reliability campaign (runs test-long first); writes conformance/reliability.json and the docs table
	@$(if $(strip $(CONFORMANCE_BUILD)),$(MAKE) $(CONFORMANCE_BUILD),true)
	$(PY) -m conformance.reliability --files $(RELIABILITY_FILES)
	@$(MAKE) generate-py >/dev/null

reliability-quick: venv  ## the reliability campaign's CI part (build/reliability/)
	@$(if $(strip $(CONFORMANCE_BUILD)),$(MAKE) $(CONFORMANCE_BUILD),true)
	$(PY) -m conformance.reliability --quick

fuzz-long: c-build  ## libFuzzer on the C codec for FUZZ_LONG_RUNS executions (outside CI)
	$(PY) -m conformance.reliability.fuzz_long --runs $(FUZZ_LONG_RUNS) --jobs $(FUZZ_LONG_JOBS)
	@$(MAKE) generate-py >/dev/null

TEST_DEPS += reliability-quick
