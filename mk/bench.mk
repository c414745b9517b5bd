# Benchmarks (issue #8): `make bench` prints the table and writes bench/results.json and
# bench/TABLE.md only. The README (tracked) changes only on `make bench-readme`, which copies
# the table of the last run into it.
BENCH_REPS ?= 5
# `cbf validate` per-file calls timed for the folder row (scaled to its 1,000 files): 1000 times them all.
BENCH_VALIDATE_CALLS ?= 100
export BENCH_VALIDATE_CALLS
.PHONY: bench bench-readme
# bytecode: a user's install has it (pip compiles the wheel's modules); without it every row's first import
# compiled cbf's modules, and the peak-RSS row moved with the tree's state (bench/NOTES.md, round 5).
bench: venv generate c-deps bytecode  ## benchmark table (Kaitai vs Python vs C); writes bench/results.json and bench/TABLE.md
	$(PY) -m bench --reps $(BENCH_REPS)

bench-readme: venv  ## copy the table of the last `make bench` (bench/results.json) into README.md
	$(PY) -m bench --readme README.md
