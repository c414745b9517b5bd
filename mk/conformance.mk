# Conformance suite (issue #3): golden cases, assembler, runner.
.PHONY: conformance golden golden-check

golden: venv  ## re-assemble conformance/golden/*.hex into .cbf
	$(PY) -m conformance.assembler

golden-check: venv  ## fail when a committed golden .cbf differs from its .hex
	$(PY) -m conformance.assembler --check

CONFORMANCE_DEPS := venv golden-check
conformance: $(CONFORMANCE_DEPS)  ## run every binding against the golden cases; writes conformance/report.json
	@$(if $(strip $(CONFORMANCE_BUILD)),$(MAKE) $(CONFORMANCE_BUILD),true)
	$(PY) -m conformance.runner
	@# The docs' traceability matrix reads report.json: keep the two together.
	@$(MAKE) generate-py >/dev/null

# The committed report and docs are the published evidence: CI fails when the
# run it just made differs from them (run `make conformance` and commit both).
.PHONY: check-report
check-report:
	@if ! git diff --exit-code --stat -- conformance/report.json generated/docs/; then \
	  echo "conformance/report.json or generated/docs/ differ from this run: commit them" >&2; exit 1; fi
	@echo "conformance report and docs are what this run measured"
