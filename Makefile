# se23 top-level Makefile.
#
#   make demo    simulated flight over LCM through the library, report + plots
#   make check   every test (installs Debian packages it needs first)
#   make lib     the library alone, host, both precisions (no CMake needed)
#   make cross   the library for Cortex-M4F (float) and Cortex-M7 (double)
#   make bench   host benchmark: filter steps vs a dense Eigen reference
#                (ns and callgrind instructions per call), routines;
#                make bench-march: the same built for MARCH (x86-64-v3)
#   make fuzz    libFuzzer targets (tests/fuzz), FUZZ_TIME seconds each
#   make doc     the reference (Doxygen) into $(BUILD)/doc/html
#   make clean   removes $(BUILD): the tree is then as cloned
#
# Firmware builds can instead compile every .c under src/ with include/ and
# port/ on their include path and -DSE23_CFG_DOUBLE=0 or 1; nothing else is
# needed (src/ is layered: base, lie, imu, cov, kalman, nav; see
# tools/layers.py).

BUILD ?= build
CC ?= cc
ARM_CC ?= arm-none-eabi-gcc
ARM_AR ?= arm-none-eabi-ar

# Parallel jobs of the test builds: one per core, but no more than the
# available memory (MemAvailable) allows at JOB_MEM_KB per job: the heaviest
# compile, tests/reference/ref_matfun.cpp, peaks at 2.5 GB resident
# (tools/doc/pages/first-run.md). JOBS=N overrides.
JOB_MEM_KB := 2600000
ifeq ($(origin JOBS),undefined)
JOBS := $(shell awk -v cores="$$(nproc 2>/dev/null || echo 1)" \
          '/^MemAvailable:/ { j = int($$2 / $(JOB_MEM_KB)); \
                              print (j < 1 ? 1 : (j > cores ? cores : j)) }' \
          /proc/meminfo 2>/dev/null)
JOBS := $(or $(JOBS),1)
endif

# Nothing is written outside $(BUILD): no Python byte code next to the
# scripts (tools/target) or in cppcheck's system addon folder, and
# matplotlib's cache and config under $(BUILD) instead of ~/.cache, ~/.config.
export PYTHONDONTWRITEBYTECODE := 1
export MPLCONFIGDIR := $(abspath $(BUILD))/matplotlib

LIB_SRCS := $(sort $(wildcard src/*/*.c src/*/*/*.c))
LIB_HDRS := $(wildcard include/se23/*.h src/*/*.h)
# The library's objects sit in one folder per build, named after their
# sources (src/nav/ins.c: ins.o), so that the gates read one folder.
LIB_OBJ_NAMES := $(notdir $(LIB_SRCS:.c=.o))
ifneq ($(words $(LIB_OBJ_NAMES)),$(words $(sort $(LIB_OBJ_NAMES))))
$(error two sources under src/ share a file name)
endif
# $(call lib_objs,folder): the library's objects in folder
lib_objs = $(addprefix $(1)/,$(LIB_OBJ_NAMES))
# $(call lib_obj_rules,folder,recipe): one rule per source, folder/name.o
# from src/<layer>/name.c; recipe sees $$< and $$@ (escape $ twice).
define lib_obj_rule
$(1)/$(notdir $(3:.c=.o)): $(3) $(LIB_HDRS)
	@mkdir -p $$(@D)
	$(2)
endef
lib_obj_rules = $(foreach s,$(LIB_SRCS),$(eval $(call lib_obj_rule,$(1),$(2),$(s))))

# Strict warnings: everything is C99 and warning-free; the library itself
# also takes the numerical-hygiene warnings.
WARN := -std=c99 -Wall -Wextra -Wpedantic -Werror
LIB_WARN := $(WARN) -Wconversion -Wdouble-promotion -Wshadow -Wvla \
            -Wstrict-prototypes -Wmissing-prototypes -Wcast-qual
LIB_CFLAGS := $(LIB_WARN) -O2 -Iinclude -Iport -fstack-usage

M4F_FLAGS := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
M7_FLAGS := -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard
ARM_CFLAGS := -ffunction-sections -fdata-sections -fcallgraph-info=su -ffp-contract=fast

.PHONY: all lib cross check demo bench deps clean

all: lib

deps:
	@sh tools/install-deps.sh $(BUILD)

# $(call lib_rules,variant,compiler,archiver,extra flags)
define lib_rules
$(call lib_obj_rules,$(BUILD)/lib-$(1),$(2) $(LIB_CFLAGS) $(4) -c $$< -o $$@)
$(BUILD)/lib-$(1)/libse23.a: $(call lib_objs,$(BUILD)/lib-$(1))
	rm -f $$@ && $(3) rcs $$@ $$^
endef

$(eval $(call lib_rules,host-double,$(CC),ar,-DSE23_CFG_DOUBLE=1))
$(eval $(call lib_rules,host-float,$(CC),ar,-DSE23_CFG_DOUBLE=0))
$(eval $(call lib_rules,m4f-float,$(ARM_CC),$(ARM_AR),-DSE23_CFG_DOUBLE=0 $(M4F_FLAGS) $(ARM_CFLAGS)))
$(eval $(call lib_rules,m7-double,$(ARM_CC),$(ARM_AR),-DSE23_CFG_DOUBLE=1 $(M7_FLAGS) $(ARM_CFLAGS)))

lib: $(BUILD)/lib-host-double/libse23.a $(BUILD)/lib-host-float/libse23.a
cross: $(BUILD)/lib-m4f-float/libse23.a $(BUILD)/lib-m7-double/libse23.a

# CMake builds the tests and the Eigen reference, one tree per precision.
# A configure that fails (a package missing) leaves no cache behind, so the
# next make configures again instead of building a tree that has no Makefile.
# $(call cmake_tree,name,SE23_DOUBLE ON|OFF,extra cmake options)
define cmake_tree
$(BUILD)/cmake-$(1)/CMakeCache.txt: CMakeLists.txt
	cmake -S . -B $(BUILD)/cmake-$(1) -DSE23_DOUBLE=$(2) -DSE23_BUILD_TESTS=ON $(3) \
	      -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null || { rm -f $$@; exit 1; }
.PHONY: tests-$(1)
tests-$(1): $(BUILD)/cmake-$(1)/CMakeCache.txt
	cmake --build $(BUILD)/cmake-$(1) -j $(JOBS)
endef
# The Eigen reference depends on neither the precision nor the C flags: the
# other trees link the double tree's libse23_reference.a instead of building
# it again (ref_matfun.cpp alone takes a minute and 2.5 GB).
REF_FROM_DOUBLE := -DSE23_REFERENCE_LIB=$(abspath $(BUILD))/cmake-double/tests/reference/libse23_reference.a
$(eval $(call cmake_tree,double,ON))
$(eval $(call cmake_tree,float,OFF,$(REF_FROM_DOUBLE)))
tests-float: tests-double
# The unit tests once more with SE23_CFG_DEEP_CHECKS=1 (no Eigen reference).
$(eval $(call cmake_tree,deep,ON,-DSE23_DEEP_CHECKS=ON -DSE23_BUILD_REFERENCE=OFF))
# The unit tests and the cross-checks of both precisions under
# AddressSanitizer and UndefinedBehaviorSanitizer (every finding aborts):
# the C code instrumented, the Eigen reference reused from the double tree
# (above).
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
$(eval $(call cmake_tree,asan-double,ON,$(REF_FROM_DOUBLE) -DCMAKE_C_FLAGS="$(SAN_FLAGS)" -DCMAKE_EXE_LINKER_FLAGS="$(SAN_FLAGS)"))
$(eval $(call cmake_tree,asan-float,OFF,$(REF_FROM_DOUBLE) -DCMAKE_C_FLAGS="$(SAN_FLAGS)" -DCMAKE_EXE_LINKER_FLAGS="$(SAN_FLAGS)"))
tests-asan-double tests-asan-float: tests-double

check: deps
	@BUILD=$(BUILD) JOBS=$(JOBS) sh tests/check.sh

-include port/target.mk
-include tools/harness.mk
-include tests/fuzz/fuzz.mk
-include tools/bench.mk
-include tools/paper.mk
-include tools/accuracy/accuracy.mk
-include tools/doc/doc.mk

clean:
	rm -rf $(BUILD)
