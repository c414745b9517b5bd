# Benchmarks (issue #8): `make bench` prints the table and writes bench/results.json.
BENCH_REPS ?= 5
.PHONY: bench
bench: venv generate c-deps  ## benchmark table (Kaitai vs Python vs C); writes bench/results.json
	$(PY) -m bench --reps $(BENCH_REPS)
