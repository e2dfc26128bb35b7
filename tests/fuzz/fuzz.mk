# libFuzzer targets (tests/fuzz/fuzz_*.c): one per public header in both
# precisions, one for the tools' LCM log reader. Included by the top-level
# Makefile after tools/harness.mk (BUILD, LIB_SRCS, LIB_HDRS, LIB_WARN, WARN
# and the generated LCM types come from there).
#
#   make fuzz          builds every target, fuzzes each for FUZZ_TIME seconds
#                      (default 60) and prints the executions per target;
#                      a crash is minimised into tests/fuzz/corpus/<target>/
#   make fuzz-build    the binaries only ($(BUILD)/fuzz/bin)
#   make fuzz-smoke    what `make check` runs (tests/check.d/75-fuzz.sh):
#                      every regression input, then FUZZ_RUNS fixed-seed runs
#
# The library is compiled with clang's coverage instrumentation and
# AddressSanitizer + UndefinedBehaviorSanitizer (every finding aborts).

FUZZ_CC ?= clang
FUZZ_TIME ?= 60
FUZZ_RUNS ?= 20000
FUZZ_NICE ?= nice -n 10
FZ := $(BUILD)/fuzz
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_COMMON := -O1 -g $(FUZZ_SAN) -Iinclude
FUZZ_LIB_CFLAGS := $(LIB_WARN) $(FUZZ_COMMON) -Iport -fsanitize=fuzzer-no-link
FUZZ_CFLAGS := $(WARN) -Wshadow $(FUZZ_COMMON) -Itests/fuzz -fsanitize=fuzzer
FUZZ_LIB_TARGETS := so3 se23 earth imu preint gauss kalman preint_unc stationary align ins
FUZZ_BINS := $(foreach t,$(FUZZ_LIB_TARGETS),$(FZ)/bin/fuzz_$(t)-double $(FZ)/bin/fuzz_$(t)-float) \
             $(FZ)/bin/fuzz_logfile

.PHONY: fuzz fuzz-build fuzz-smoke

# $(call fuzz_prec,double|float,0|1)
define fuzz_prec
$(call lib_obj_rules,$(FZ)/lib-$(1),$(FUZZ_CC) $(FUZZ_LIB_CFLAGS) -DSE23_CFG_DOUBLE=$(2) -c $$< -o $$@)
$(FZ)/lib-$(1)/libse23.a: $(call lib_objs,$(FZ)/lib-$(1))
	rm -f $$@ && ar rcs $$@ $$^
$(FZ)/bin/fuzz_%-$(1): tests/fuzz/fuzz_%.c tests/fuzz/fuzz.h $(FZ)/lib-$(1)/libse23.a $(LIB_HDRS)
	@mkdir -p $$(dir $$@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -DSE23_CFG_DOUBLE=$(2) $$< $(FZ)/lib-$(1)/libse23.a -lm -o $$@
endef
$(eval $(call fuzz_prec,double,1))
$(eval $(call fuzz_prec,float,0))

# The log reader and the generated LCM decoders, instrumented alike (no
# library: the target feeds bytes to tools/lcm/logfile.c and decodes each
# event with the types of tools/lcm/*.lcm, as se23-ins and se23-report do).
$(FZ)/lcm/%.o: $(H_GEN)/%.c $(H_GEN)/.stamp
	@mkdir -p $(dir $@)
	$(FUZZ_CC) -std=c99 -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer-no-link -I$(H_GEN) $(LCM_CFLAGS) \
	    -c $< -o $@
$(FZ)/lcm/logfile.o: tools/lcm/logfile.c tools/lcm/logfile.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(WARN) -Wshadow -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer-no-link $(LCM_CFLAGS) \
	    -c $< -o $@
$(FZ)/bin/fuzz_logfile: tests/fuzz/fuzz_logfile.c tests/fuzz/fuzz.h $(FZ)/lcm/logfile.o \
                        $(patsubst $(H_GEN)/%.c,$(FZ)/lcm/%.o,$(LCM_GEN_C))
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(WARN) -Wshadow -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer -Iinclude -Itests/fuzz -Itools/lcm \
	    -isystem $(H_GEN) $(LCM_CFLAGS) $(filter %.c %.o,$^) $(LCM_LIBS) -o $@

fuzz-build: $(FUZZ_BINS)

fuzz: fuzz-build
	@FUZZ_NICE="$(FUZZ_NICE)" sh tests/fuzz/run.sh fuzz $(FZ) $(FUZZ_TIME)

fuzz-smoke: fuzz-build
	@sh tests/fuzz/run.sh smoke $(FZ) $(FUZZ_RUNS)
