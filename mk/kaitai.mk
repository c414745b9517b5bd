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
# The Java parser's source path follows its package (ksc-options.json, written by cbfgen).
KAITAI_JAVA_PACKAGE := $(shell sed -n 's/^ *"java_package": *"\([^"]*\)".*/\1/p' generated/kaitai/ksc-options.json 2>/dev/null)
KAITAI_JAVA_SRC := generated/kaitai/java/src/main/java/$(subst .,/,$(KAITAI_JAVA_PACKAGE))/Cbf.java
KSC_OUTPUTS := generated/kaitai/python/cbf_kaitai/cbf.py generated/kaitai/javascript/Cbf.js $(KAITAI_JAVA_SRC) generated/kaitai/go/cbf.go
KSC_MISSING = $(filter-out $(wildcard $(KSC_OUTPUTS)),$(KSC_OUTPUTS))
.PHONY: ksc-force
$(STAMPS)/ksc: generated/kaitai/cbf.ksy.json generated/kaitai/ksc-options.json generator/cbfgen/emit/kaitai/ksc_driver.js node_modules/.stamp $(if $(KSC_MISSING),ksc-force)
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

# The Java testee: the runtime jar the parser's pom (generated/kaitai/java/pom.xml, the
# Maven package) depends on, fetched by Maven; the parser (package $(KAITAI_JAVA_PACKAGE))
# and the testee, which imports it, compiled with javac. go-offline also puts the pom's
# plugins in ~/.m2, so that a later `mvn install` of the parser needs no network.
KAITAI_JAVA := build/kaitai-java
KAITAI_JAR := $(KAITAI_JAVA)/lib/kaitai-struct-runtime-0.11.jar
.PHONY: kaitai-java-build
$(KAITAI_JAR): generated/kaitai/java/pom.xml
	mvn -q -B -Dstyle.color=never -f generated/kaitai/java/pom.xml dependency:go-offline dependency:copy-dependencies \
	  -DincludeScope=runtime -DoutputDirectory=$(CURDIR)/$(KAITAI_JAVA)/lib
	@touch $@
$(KAITAI_JAVA)/classes/Testee.class: $(KAITAI_JAVA_SRC) generated/kaitai/java-testee/Testee.java $(KAITAI_JAR)
	@rm -rf $(KAITAI_JAVA)/classes && mkdir -p $(KAITAI_JAVA)/classes
	javac -nowarn -encoding UTF-8 --release 11 -d $(KAITAI_JAVA)/classes -cp $(KAITAI_JAR) $(KAITAI_JAVA_SRC) generated/kaitai/java-testee/Testee.java
kaitai-java-build: $(KAITAI_JAVA)/classes/Testee.class  ## build the Kaitai Java conformance testee
CONFORMANCE_BUILD += kaitai-java-build
# before the tests: the Maven consumer test (tests/test_kaitai_packages.py) reads ~/.m2 as a mirror
TEST_DEPS += kaitai-java-build
