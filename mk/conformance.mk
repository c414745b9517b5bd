# Conformance suite (issue #3): golden cases, assembler, runner.
.PHONY: conformance golden golden-check

# The docs' golden pages are made from the .cbf files: `make golden` regenerates them, so that a
# revision made in the README's order (generate, then golden) leaves generated/ fresh.
golden: venv  ## re-assemble conformance/golden/*.hex into .cbf, then regenerate what is made from them
	$(PY) -m conformance.assembler
	@$(MAKE) --no-print-directory generate

GOLDEN_FILES := $(wildcard conformance/golden/*)
ASSEMBLER_FILES := $(wildcard conformance/assembler/*.py)
golden-check: venv $(STAMPS)/golden-check  ## fail when a committed golden .cbf differs from its .hex
$(STAMPS)/golden-check: $(GOLDEN_FILES) $(ASSEMBLER_FILES) generator/cbfgen/registry.py spec/cbf.yaml $(VENV)/.stamp
	$(PY) -m conformance.assembler --check
	@mkdir -p $(@D) && touch $@

# The suite runs again only when something it reads changed: the generated bindings, the
# golden cases, the runner, testees, failure lists, or a built testee (not Maven's target/, which the
# README's `mvn install` of the Java parser writes). `make conformance
# FORCE_CONFORMANCE=1` runs it regardless.
CONFORMANCE_INPUTS = $(shell find generated conformance -type f -not -path '*/__pycache__/*' \
  -not -name report.json -not -name 'report.json.tmp' -not -path 'generated/docs/*' \
  -not -path 'generated/kaitai/java/target/*' 2>/dev/null) \
  $(wildcard build/c/cbf_testee build/kaitai-go/testee build/kaitai-java/classes/Testee.class)
CONFORMANCE_DEPS := venv golden-check
conformance: $(CONFORMANCE_DEPS)  ## run every binding against the golden cases; writes conformance/report.json
	@$(if $(strip $(CONFORMANCE_BUILD)),$(MAKE) $(CONFORMANCE_BUILD),true)
	@$(if $(FORCE_CONFORMANCE),rm -f $(STAMPS)/conformance,true)
	@$(MAKE) $(STAMPS)/conformance

$(STAMPS)/conformance: $(CONFORMANCE_INPUTS)
	$(PY) -m conformance.runner
	@# The docs' traceability matrix reads report.json: keep the two together.
	@$(MAKE) generate-py >/dev/null
	@mkdir -p $(@D) && touch $@

# After a revision: every binding runs, each failure list is rewritten to its failing cases by
# reason (a class, or a listed `~ REGEX` that still matches; conformance/runner/reasons.py) and its
# diff is printed to review before committing. A list naming a case that now passes, or one
# no golden case has, loses it; a new failure gains its class.
.PHONY: failures
failures: $(CONFORMANCE_DEPS)  ## rewrite conformance/failures/*.txt to this run's failures by reason; prints the diff to review
	@$(if $(strip $(CONFORMANCE_BUILD)),$(MAKE) $(CONFORMANCE_BUILD),true)
	$(PY) -m conformance.runner --fix
	@$(MAKE) generate-py >/dev/null
	@mkdir -p $(STAMPS) && touch $(STAMPS)/conformance
	@git diff --stat -- conformance/failures 2>/dev/null || true

# The committed report and docs are the published evidence: CI fails when the
# run it just made differs from them (run `make conformance` and commit both).
.PHONY: check-report
check-report:
	@if ! git diff --exit-code --stat -- conformance/report.json generated/docs/; then \
	  echo "conformance/report.json or generated/docs/ differ from this run: commit them" >&2; exit 1; fi
	@echo "conformance report and docs are what this run measured"
