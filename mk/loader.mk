# The spec loader (generator/cbfgen/loader/): its pass list in generator/README.md, and the
# complexity ceiling of its functions (issue 33, point 6), counted by radon and lizard.
.PHONY: loader-readme loader-complexity
loader-readme: venv  ## write the loader's pass list (from the code) into generator/README.md
	$(PY) -m cbfgen.loader.readme generator/README.md

LOADER_CC_MAX ?= 25
loader-complexity: venv  ## radon and lizard: no function of the loader above cyclomatic complexity 25
	$(PY) -m radon cc -s -n F generator/cbfgen/loader --total-average
	$(PY) -m lizard -w -C $(LOADER_CC_MAX) generator/cbfgen/loader
