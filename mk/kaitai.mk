# Kaitai Struct (issue #4): generated/kaitai/cbf.ksy from the spec (cbfgen), compiled
# by kaitai-struct-compiler 0.11.0 (npm, pinned in package-lock.json) to parsers in
# Python, JavaScript, Java and Go. Conformance testees: Python and JavaScript.
KAITAI_LANGS := python javascript java go

node_modules/.stamp: package.json package-lock.json
	npm ci --no-audit --no-fund --loglevel=error
	@touch $@

.PHONY: kaitai-setup generate-ksc
kaitai-setup: node_modules/.stamp  ## npm ci: the Kaitai compiler and JavaScript runtime

generate-ksc: kaitai-setup generate-py  ## compile generated/kaitai/cbf.ksy to $(KAITAI_LANGS)
	node generator/cbfgen/emit/kaitai/ksc_driver.js generated/kaitai/cbf.ksy.json generated/kaitai $(KAITAI_LANGS) >/dev/null

GENERATE_POST += generate-ksc
CONFORMANCE_BUILD += kaitai-setup
