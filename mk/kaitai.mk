# Kaitai Struct (issue #4): generated/kaitai/cbf.ksy from the spec (cbfgen), compiled
# by kaitai-struct-compiler 0.11.0 (npm, pinned in package-lock.json) to parsers in
# Python, JavaScript, Java and Go. Conformance testees: Python and JavaScript.
KAITAI_LANGS := python javascript java go

node_modules/.stamp: package.json package-lock.json | setup
	npm ci --no-audit --no-fund --loglevel=error
	@touch $@

.PHONY: kaitai-setup generate-ksc
kaitai-setup: node_modules/.stamp  ## npm ci: the Kaitai compiler and JavaScript runtime

generate-ksc: kaitai-setup generate-py  ## compile generated/kaitai/cbf.ksy to $(KAITAI_LANGS)
	@$(MAKE) $(STAMPS)/ksc

# ksc runs only when the .ksy, the driver or the compiler changed; it rewrites only
# the files whose content changed. A missing output file forces a run too.
KSC_OUTPUTS := generated/kaitai/python/cbf_kaitai/cbf.py generated/kaitai/javascript/Cbf.js generated/kaitai/java/Cbf.java generated/kaitai/go/cbf.go
KSC_MISSING = $(filter-out $(wildcard $(KSC_OUTPUTS)),$(KSC_OUTPUTS))
.PHONY: ksc-force
$(STAMPS)/ksc: generated/kaitai/cbf.ksy.json generator/cbfgen/emit/kaitai/ksc_driver.js node_modules/.stamp $(if $(KSC_MISSING),ksc-force)
	node generator/cbfgen/emit/kaitai/ksc_driver.js generated/kaitai/cbf.ksy.json generated/kaitai $(KAITAI_LANGS) >/dev/null
	@mkdir -p $(@D) && touch $@

GENERATE_POST += generate-ksc
CONFORMANCE_BUILD += kaitai-setup

# The Go testee: the generated parser and testee (package cbf) plus main.go, with the
# runtime pinned by conformance/testees/kaitai-go/go.mod and go.sum.
KAITAI_GO := build/kaitai-go
.PHONY: kaitai-go-build
$(KAITAI_GO)/testee: generated/kaitai/go/cbf.go generated/kaitai/go-testee/testee.go conformance/testees/kaitai-go/main.go conformance/testees/kaitai-go/go.mod conformance/testees/kaitai-go/go.sum
	@mkdir -p $(KAITAI_GO)/cbf
	cp conformance/testees/kaitai-go/go.mod conformance/testees/kaitai-go/go.sum conformance/testees/kaitai-go/main.go $(KAITAI_GO)/
	cp generated/kaitai/go/cbf.go generated/kaitai/go-testee/testee.go $(KAITAI_GO)/cbf/
	cd $(KAITAI_GO) && GOFLAGS=-mod=readonly go build -o testee .
kaitai-go-build: $(KAITAI_GO)/testee  ## build the Kaitai Go conformance testee
CONFORMANCE_BUILD += kaitai-go-build

# The Java testee: the runtime jar pinned by conformance/testees/kaitai-java/pom.xml
# (fetched by Maven), the generated parser and testee compiled with javac.
KAITAI_JAVA := build/kaitai-java
KAITAI_JAR := $(KAITAI_JAVA)/lib/kaitai-struct-runtime-0.11.jar
.PHONY: kaitai-java-build
$(KAITAI_JAR): conformance/testees/kaitai-java/pom.xml
	cd conformance/testees/kaitai-java && mvn -q -B dependency:copy-dependencies -DoutputDirectory=$(CURDIR)/$(KAITAI_JAVA)/lib
	@touch $@
$(KAITAI_JAVA)/classes/Testee.class: generated/kaitai/java/Cbf.java generated/kaitai/java/Testee.java $(KAITAI_JAR)
	@mkdir -p $(KAITAI_JAVA)/classes
	javac -nowarn -encoding UTF-8 -d $(KAITAI_JAVA)/classes -cp $(KAITAI_JAR) generated/kaitai/java/Cbf.java generated/kaitai/java/Testee.java
kaitai-java-build: $(KAITAI_JAVA)/classes/Testee.class  ## build the Kaitai Java conformance testee
CONFORMANCE_BUILD += kaitai-java-build
