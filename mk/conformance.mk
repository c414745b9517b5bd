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
