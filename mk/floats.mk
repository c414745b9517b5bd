# The CUT float formatter over all 2^32 binary32 patterns (issue 13, item 1): each finite
# pattern reads back byte-exact from the text cbf.floats.format_float writes, each NaN and
# infinity is written as cbf_record. tests/floats/exhaustive.c is the formatter's C twin;
# tests/test_float_format.py checks (in `make test`) that the twin writes what the Python
# formatter writes, on the edges and a sample. About 20 CPU-minutes, so outside `make test`:
# the sweep runs in FLOATS_JOBS chunks in parallel and writes build/floats/exhaustive.txt.
FLOATS_OUT := build/floats
FLOATS_JOBS ?= $(shell nproc)
FLOATS_CHUNKS := 64
.PHONY: floats-exhaustive

$(FLOATS_OUT)/exhaustive: tests/floats/exhaustive.c
	@mkdir -p $(FLOATS_OUT)
	$(C_CC) -std=c99 -O2 -Wall -Wextra -Wconversion -Werror -o $@ $< -lm

floats-exhaustive: venv $(FLOATS_OUT)/exhaustive  ## prove the CUT float formatter over all 2^32 binary32 patterns
	$(PY) -m pytest -p no:cacheprovider -q tests/test_float_format.py
	@start=$$(date +%s); \
	seq 0 $$(( $(FLOATS_CHUNKS) - 1 )) | xargs -P $(FLOATS_JOBS) -I{} sh -c \
	  'step=$$(( (1 << 32) / $(FLOATS_CHUNKS) )); $(FLOATS_OUT)/exhaustive $$(( {} * step )) $$(( {} * step + step - 1 )) > $(FLOATS_OUT)/chunk.{}.txt' \
	  || { cat $(FLOATS_OUT)/chunk.*.txt; echo "floats-exhaustive: FAILED" >&2; exit 1; }; \
	secs=$$(( $$(date +%s) - start )); \
	cat $(FLOATS_OUT)/chunk.*.txt | awk -v secs=$$secs -v jobs=$(FLOATS_JOBS) ' \
	  /finite read back/ { split($$0, a, ": "); split(a[2], b, " "); good += b[1]; rec += b[6]; bad += b[11]; n++ } \
	  /compared with/ { for (i = 1; i <= NF; i++) if ($$i == "fallbacks") fb += $$(i+1); for (i = 1; i <= NF; i++) if ($$i == "compared") cmp += $$(i-1) } \
	  END { printf "all 2^32 binary32 patterns (%d chunks): %.0f finite read back byte-exact, %.0f NaN/infinity written as cbf_record, %.0f failed; %.0f decided by the exact test, %.0f compared with the plain loop; %d s on %d jobs\n", n, good, rec, bad, fb, cmp, secs, jobs; \
	        exit (bad != 0 || good + rec != 4294967296) }' | tee $(FLOATS_OUT)/exhaustive.txt
