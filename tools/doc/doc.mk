# make doc: the reference, Doxygen (tools/doc/Doxyfile) over the public
# headers include/se23/, the manual pages tools/doc/pages/*.md and the
# README as the main page, into $(BUILD)/doc/html/ (index.html printed).
# Doxygen's warnings go to $(BUILD)/doc/warnings.txt; any warning fails
# the target (the Doxyfile's WARN_AS_ERROR = FAIL_ON_WARNINGS, and their
# count here): the reference is still written, and the count per file and
# the first warnings are printed. make check (step 52-doc) builds it the
# same way and requires zero warnings, audits Doxygen's XML for what it
# does not warn about (an enumerator, a header without @file), and shows
# that planted undocumented symbols fail it (issue 36).
DOC_MAX_SHOWN := 20

.PHONY: doc
doc: deps
	@mkdir -p $(BUILD)/doc
	@out=$(BUILD)/doc; \
	SE23_DOC_OUT=$(abspath $(BUILD))/doc doxygen tools/doc/Doxyfile 2>$$out/warnings.txt; \
	rc=$$?; \
	n=$$(grep -cE '(warning|error): ' $$out/warnings.txt); \
	echo "se23 reference: $$out/html/index.html; $$n Doxygen warnings ($$out/warnings.txt)"; \
	if [ "$$n" -ne 0 ] || [ "$$rc" -ne 0 ]; then \
	    sed -nE 's|^$(abspath .)/||; s/^([^ :]*):[0-9]+: (warning|error): .*/\1/p; s/^(warning|error): .*/(configuration)/p' \
	        $$out/warnings.txt | sort | uniq -c; \
	    grep -E '(warning|error): ' $$out/warnings.txt | sed 's|^$(abspath .)/||' | head -n $(DOC_MAX_SHOWN); \
	    echo "make doc: failed (doxygen status $$rc, $$n warnings; every one must be fixed)"; \
	    exit 1; \
	fi

# make doc-tables: the measured tables of the manual pages (per-function
# instruction counts, stack and size on Cortex-M, the host benchmark, the
# fuzzing executions, the soak runs), each pasted from the file its command
# wrote into $(BUILD) between the page's <!-- table:NAME begin/end -->
# markers (tools/doc/tables.py; `tables.py --list` names them and their
# commands). A table whose file is missing is kept as it is. make check
# verifies current the tables it measures itself (40-target, 45-gates,
# 80-bench, 85-soak) and the rows of the fuzzing table (75-fuzz).
.PHONY: doc-tables
PY3 ?= /usr/bin/python3
doc-tables:
	@$(PY3) tools/doc/tables.py --build $(BUILD)
