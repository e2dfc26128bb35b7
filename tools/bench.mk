# make bench: the host benchmark (tools/bench/run.sh): the composite steps
# of a filter against a dense Eigen reference in the same process, wall
# time and callgrind instructions, then instructions per routine; float and
# double builds. Included by the top-level Makefile.
.PHONY: bench bench-bins bench-march
BENCH_CFLAGS := $(WARN) -O2 -Iinclude -Itests/support
BENCH_CXXFLAGS := -std=c++17 -Wall -Wextra -Wpedantic -Werror -O2 -Iinclude \
                  -isystem /usr/include/eigen3
# The inputs come from the tests' seeded generator (as the paper tools do).
BENCH_SRCS := $(wildcard tools/bench/*.c tools/bench/*.cpp) tests/support/se23_rng.c
BENCH_HDRS := $(wildcard tools/bench/*.h tools/bench/*.hpp) tests/support/se23_rng.h $(LIB_HDRS)

# $(call bench_rules,precision,SE23_CFG_DOUBLE)
define bench_rules
$(BUILD)/bench-$(1)/%.o: tools/bench/%.c $(BENCH_HDRS) | $(BUILD)/bench-$(1)
	$(CC) $(BENCH_CFLAGS) -DSE23_CFG_DOUBLE=$(2) -c $$< -o $$@
$(BUILD)/bench-$(1)/%.o: tests/support/%.c $(BENCH_HDRS) | $(BUILD)/bench-$(1)
	$(CC) $(BENCH_CFLAGS) -DSE23_CFG_DOUBLE=$(2) -c $$< -o $$@
$(BUILD)/bench-$(1)/%.o: tools/bench/%.cpp $(BENCH_HDRS) | $(BUILD)/bench-$(1)
	$(CXX) $(BENCH_CXXFLAGS) -DSE23_CFG_DOUBLE=$(2) -c $$< -o $$@
$(BUILD)/bench-$(1)/se23-bench: $(patsubst %,$(BUILD)/bench-$(1)/%.o,$(notdir $(basename $(BENCH_SRCS)))) \
                                $(BUILD)/lib-host-$(1)/libse23.a
	$(CXX) $$^ -lm -o $$@
$(BUILD)/bench-$(1):
	mkdir -p $$@
endef
$(eval $(call bench_rules,double,1))
$(eval $(call bench_rules,float,0))

bench-bins: $(BUILD)/bench-double/se23-bench $(BUILD)/bench-float/se23-bench

bench: deps bench-bins
	@CC="$(CC)" CXX="$(CXX)" \
	    BENCH_FLAGS="library $(filter-out -W% -I%,$(LIB_CFLAGS)), reference $(filter-out -W% -I% -isystem /usr/include/eigen3,$(BENCH_CXXFLAGS))$(if $(BENCH_MARCH),, no -march)" \
	    sh tools/bench/run.sh $(BUILD)

# make bench-march [MARCH=x86-64-v3]: the same benchmark with the library
# and the reference both built for MARCH (x86-64-v3: AVX2 and fused
# multiply-add, every x86-64 since 2013-2015), in $(BUILD)/march-MARCH.
MARCH ?= x86-64-v3
bench-march: deps
	@$(MAKE) --no-print-directory bench BUILD=$(BUILD)/march-$(MARCH) BENCH_MARCH=$(MARCH) \
	    LIB_CFLAGS='$(LIB_CFLAGS) -march=$(MARCH)' BENCH_CXXFLAGS='$(BENCH_CXXFLAGS) -march=$(MARCH)'
