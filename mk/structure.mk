# The generator's structure (issue 33): its import graph as a picture, and the complexity ceiling over
# all of generator/ (tests/test_import_graph.py and tests/test_complexity.py hold both in `make test`).
.PHONY: import-graph complexity
IMPORT_GRAPH := build/import-graph.svg
import-graph: venv  ## draw generator/'s import graph with pydeps into build/import-graph.svg
	@mkdir -p build
	cd generator && ../$(PY) -m pydeps cbfgen --no-config --noshow --only cbfgen --cluster --max-bacon 0 \
	  --rankdir TB -T svg -o ../$(IMPORT_GRAPH)
	@echo "$(IMPORT_GRAPH)"

complexity: venv  ## radon and lizard over all of generator/: the functions above cyclomatic complexity 25
	$(PY) -m radon cc -s -n E generator
	$(PY) -m lizard -w -C 25 generator
