# Cortex-M targets on QEMU (included by the top-level Makefile; reuses its
# BUILD, WARN, LIB_CFLAGS, M4F_FLAGS, M7_FLAGS, ARM_CC and the library rules
# for $(BUILD)/lib-<variant>/libse23.a).
#
#   make target        build the target images for both boards
#   make test-target   run them in qemu-system-arm (exit status = failures)
#
# Variants: m4f-float on mps2-an386 (Cortex-M4F, float build) and
# m7-double on mps2-an500 (Cortex-M7 with double FPU, double build).

TGT := $(BUILD)/target
# One image run takes ~0.1 s (tools/target/qemu-run.sh BOARD IMAGE).
QEMU_RUN := sh tools/target/qemu-run.sh

TGT_CFLAGS := $(WARN) -O2 -g -ffunction-sections -fdata-sections \
              -Iinclude -Iport
TGT_LDFLAGS := -nostartfiles --specs=nano.specs --specs=rdimon.specs \
               -Lport/cortex-m -Wl,--gc-sections
TGT_PORT_OBJS = $(TGT)/$(1)/port/startup.o $(TGT)/$(1)/port/se23_port.o
TGT_TV_OBJS = $(TGT)/$(1)/tv_runner.o $(call TGT_TV_LIB_OBJS,$(1))
# The adapters of every routine, shared by the test and benchmark images.
TGT_TV_LIB_OBJS = $(patsubst %,$(TGT)/$(1)/%.o,tv_adapters tv_custom tv_custom_gauss tv_custom_geo)

# Reference vectors: tools/target/gen_vectors (host, C++) from the Eigen
# reference library that the CMake test tree builds (tests/reference).
TGT_REF_LIB := $(BUILD)/cmake-double/tests/reference/libse23_reference.a
TGT_GEN := $(TGT)/gen_vectors
# The routine whose first expected value the runner's own test corrupts.
TGT_CORRUPT := se23_so3_exp

# The navigation-filter replay (tests/target/ins_replay.c): recorded
# sequences and the host's double reference from tools/target/gen_ins_replay
# (C, linked with the host double library; the same driver
# tests/target/ins_replay_drive.c runs on both sides).
TGT_INSR_GEN := $(TGT)/gen_ins_replay
TGT_INSR_OBJS = $(TGT)/$(1)/ins_replay.o $(TGT)/$(1)/ins_replay_drive.o
$(TGT_INSR_GEN): tools/target/gen_ins_replay.c \
                 tools/target/gen_print.c tools/target/gen_print.h \
                 tests/target/ins_replay_drive.c tests/target/ins_replay.h \
                 tests/support/se23_rng.c tests/support/se23_rng.h \
                 $(LIB_HDRS) $(BUILD)/lib-host-double/libse23.a
	mkdir -p $(@D)
	$(CC) $(WARN) -O2 -Iinclude -Itests/target -Itests/support -DSE23_CFG_DOUBLE=1 \
	    $(filter %.c,$^) $(BUILD)/lib-host-double/libse23.a -lm -o $@

# The real walk replayed (tests/target/walk_replay.c): the x-io walk
# (tools/data/xio-gait-tracking) as se23-import reads it, and the host's run
# of the filter through it in the image's precision, from
# tools/target/gen_walk_replay (C, built once per precision against the
# host library of that precision and the importer's parsing code; the
# drivers tests/target/ins_replay_drive.c and walk_replay_drive.c run on
# both sides).
TGT_WALK_CSV := tools/data/xio-gait-tracking/short_walk.csv
TGT_WALK_OBJS = $(patsubst %,$(TGT)/$(1)/%.o,walk_replay walk_replay_drive walk_replay_check \
                  ins_replay_drive)
TGT_WALK_GEN_SRCS := tools/target/gen_walk_replay.c tools/target/gen_print.c \
                     tests/target/ins_replay_drive.c tests/target/walk_replay_drive.c \
                     tools/import/csv.c tools/import/row.c tools/import/hygiene.c \
                     tools/lcm/ldmath.c
# $(call tgt_walk_gen,float|double,SE23_CFG_DOUBLE)
define tgt_walk_gen
$(TGT)/gen_walk_replay_$(1): $(TGT_WALK_GEN_SRCS) tools/target/gen_print.h \
                             tests/target/ins_replay.h tests/target/walk_replay.h \
                             $(wildcard tools/import/*.h) $(LIB_HDRS) $(BUILD)/lib-host-$(1)/libse23.a
	mkdir -p $$(@D)
	$(CC) $(WARN) -O2 -Iinclude -Itests/target -DSE23_CFG_DOUBLE=$(2) \
	    $(TGT_WALK_GEN_SRCS) $(BUILD)/lib-host-$(1)/libse23.a -lm -o $$@
endef
$(eval $(call tgt_walk_gen,float,0))
$(eval $(call tgt_walk_gen,double,1))

# A part of the real car drive replayed (tests/target/drive_replay.c): the
# rtklibexplorer drive 0708's first 70 s (the rest, the alignment, the
# heading from the course, 20 s of driving with fixes, the last 10 s
# without) as se23-drive-import writes it with the drive's installation
# (tools/drive/rtklibexplorer-0708.conf), and the host's run of the filter
# through it in the image's precision, from tools/target/gen_drive_replay
# (C, built once per precision; it reads the importer's LCM log with the
# harness's log reader and decoders; the driver ins_replay_drive.c runs on
# both sides, the checks walk_replay_check.c are the walk's).
TGT_DRIVE_DATA := tools/data/car/rtklibexplorer-drive-0708
TGT_DRIVE_LOG := $(TGT)/drive_replay.log
TGT_DRIVE_IMPORT := $(BUILD)/harness/bin/se23-drive-import
TGT_DRIVE_OBJS = $(patsubst %,$(TGT)/$(1)/%.o,drive_replay walk_replay_check ins_replay_drive)
TGT_DRIVE_GEN_SRCS := tools/target/gen_drive_replay.c tools/target/gen_print.c \
                      tests/target/ins_replay_drive.c tools/lcm/logfile.c
$(TGT_DRIVE_LOG): $(TGT_DRIVE_IMPORT) $(wildcard $(TGT_DRIVE_DATA)/*) tools/drive/rtklibexplorer-0708.conf
	mkdir -p $(@D)
	. tools/drive/rtklibexplorer-0708.conf && $(TGT_DRIVE_IMPORT) --rtklib \
	    $(TGT_DRIVE_DATA)/imu_1934.csv $(TGT_DRIVE_DATA)/imu_1934.csv.tag \
	    $(TGT_DRIVE_DATA)/gnss_1934_sf.pos --axes="$$AXES" --imu-time-offset "$$IMU_TIME_OFFSET" \
	    --duration 70 --outage 60,10 --out "file://$@?mode=w" > $(@:.log=-import.txt) 2>&1 || \
	    { cat $(@:.log=-import.txt); rm -f $@; exit 1; }
# $(call tgt_drive_gen,float|double,SE23_CFG_DOUBLE)
define tgt_drive_gen
$(TGT)/gen_drive_replay_$(1): $(TGT_DRIVE_GEN_SRCS) tools/target/gen_print.h tools/lcm/logfile.h \
                              tools/lcm/harness.h tests/target/ins_replay.h \
                              tests/target/drive_replay.h $(BUILD)/harness/libse23lcm.a \
                              $(LIB_HDRS) $(BUILD)/lib-host-$(1)/libse23.a
	mkdir -p $$(@D)
	$(CC) $(WARN) -O2 -Iinclude -Itests/target -isystem $(BUILD)/harness/gen $$(LCM_CFLAGS) \
	    -DSE23_CFG_DOUBLE=$(2) $(TGT_DRIVE_GEN_SRCS) $(BUILD)/harness/libse23lcm.a \
	    $(BUILD)/lib-host-$(1)/libse23.a $$(LCM_LIBS) -lm -o $$@
endef
$(eval $(call tgt_drive_gen,float,0))
$(eval $(call tgt_drive_gen,double,1))

TGT_VARIANTS := m4f-float m7-double
TGT_BOARD_m4f-float := mps2-an386
TGT_BOARD_m7-double := mps2-an500

.PHONY: target test-target tgt-always

$(TGT_REF_LIB): $(BUILD)/cmake-double/CMakeCache.txt tgt-always
	cmake --build $(BUILD)/cmake-double --target se23_reference -j 1 >/dev/null
$(TGT_GEN): $(wildcard tools/target/gen_*.cpp tools/target/gen_*.hpp) tests/target/tv.h tests/target/tv_list.h \
            $(wildcard tests/reference/*.hpp) $(LIB_HDRS) $(TGT_REF_LIB)
	mkdir -p $(@D)
	$(CXX) -std=c++17 -O1 -Wall -Wextra -Werror -isystem /usr/include/eigen3 \
	    -Iinclude -Itests/reference -Itests/target -DSE23_CFG_DOUBLE=1 \
	    $(filter %.cpp,$^) $(TGT_REF_LIB) -o $@

# $(call tgt_variant,variant,arch flags,SE23_CFG_DOUBLE)
define tgt_variant
$(TGT)/$(1)/port/%.o: port/cortex-m/%.S | $(TGT)/$(1)/port
	$(ARM_CC) $(2) -c $$< -o $$@
$(TGT)/$(1)/port/%.o: port/cortex-m/%.c port/se23_port.h | $(TGT)/$(1)/port
	$(ARM_CC) $(2) $(TGT_CFLAGS) -DSE23_CFG_DOUBLE=$(3) -c $$< -o $$@
$(TGT)/$(1)/%.o: tests/target/%.c $(LIB_HDRS) $(wildcard tests/target/*.h) | $(TGT)/$(1)/port
	$(ARM_CC) $(2) $(TGT_CFLAGS) -Itests/target -I$(TGT)/$(1) \
	    -DSE23_CFG_DOUBLE=$(3) -c $$< -o $$@
$(TGT)/$(1)/%.o: $(TGT)/$(1)/%.c tests/target/tv.h tests/target/tv_list.h $(LIB_HDRS)
	$(ARM_CC) $(2) $(TGT_CFLAGS) -Itests/target -DSE23_CFG_DOUBLE=$(3) -c $$< -o $$@
$(TGT)/$(1)/tv_data.c: $(TGT_GEN) | $(TGT)/$(1)/port
	$(TGT_GEN) $(if $(filter 1,$(3)),double,float) > $$@.tmp && mv $$@.tmp $$@
$(TGT)/$(1)/tv_data_corrupt.c: $(TGT_GEN) | $(TGT)/$(1)/port
	$(TGT_GEN) $(if $(filter 1,$(3)),double,float) --corrupt $(TGT_CORRUPT) > $$@.tmp && mv $$@.tmp $$@
$(TGT)/$(1)/ins_replay_data.c: $(TGT_INSR_GEN) | $(TGT)/$(1)/port
	$(TGT_INSR_GEN) > $$@.tmp 2> $$(@:.c=.log) || { cat $$(@:.c=.log); exit 1; }
	mv $$@.tmp $$@
$(TGT)/$(1)/ins_replay_data_corrupt.c: $(TGT_INSR_GEN) | $(TGT)/$(1)/port
	$(TGT_INSR_GEN) --corrupt > $$@.tmp 2> $$(@:.c=.log) || { cat $$(@:.c=.log); exit 1; }
	mv $$@.tmp $$@
$(TGT)/$(1)/ins_replay_data.o $(TGT)/$(1)/ins_replay_data_corrupt.o: tests/target/ins_replay.h
$(TGT)/$(1)/walk_replay_data.c: $(TGT)/gen_walk_replay_$(if $(filter 1,$(3)),double,float) \
                                $(TGT_WALK_CSV) | $(TGT)/$(1)/port
	$$< $(TGT_WALK_CSV) > $$@.tmp 2> $$(@:.c=.log) || { cat $$(@:.c=.log); exit 1; }
	mv $$@.tmp $$@
$(TGT)/$(1)/walk_replay_data_corrupt.c: $(TGT)/gen_walk_replay_$(if $(filter 1,$(3)),double,float) \
                                        $(TGT_WALK_CSV) | $(TGT)/$(1)/port
	$$< --corrupt $(TGT_WALK_CSV) > $$@.tmp 2> $$(@:.c=.log) || { cat $$(@:.c=.log); exit 1; }
	mv $$@.tmp $$@
$(TGT)/$(1)/walk_replay_data.o $(TGT)/$(1)/walk_replay_data_corrupt.o: tests/target/ins_replay.h \
                                                                       tests/target/walk_replay.h
$(TGT)/$(1)/drive_replay_data.c: $(TGT)/gen_drive_replay_$(if $(filter 1,$(3)),double,float) \
                                 $(TGT_DRIVE_LOG) | $(TGT)/$(1)/port
	$$< $(TGT_DRIVE_LOG) > $$@.tmp 2> $$(@:.c=.log) || { cat $$(@:.c=.log); exit 1; }
	mv $$@.tmp $$@
$(TGT)/$(1)/drive_replay_data_corrupt.c: $(TGT)/gen_drive_replay_$(if $(filter 1,$(3)),double,float) \
                                         $(TGT_DRIVE_LOG) | $(TGT)/$(1)/port
	$$< --corrupt $(TGT_DRIVE_LOG) > $$@.tmp 2> $$(@:.c=.log) || { cat $$(@:.c=.log); exit 1; }
	mv $$@.tmp $$@
$(TGT)/$(1)/drive_replay_data.o $(TGT)/$(1)/drive_replay_data_corrupt.o: tests/target/ins_replay.h \
                                                                         tests/target/drive_replay.h
$(TGT)/$(1)/port:
	mkdir -p $$@
$(TGT)/$(1)/tv_test.elf: $(call TGT_TV_OBJS,$(1)) $(TGT)/$(1)/tv_data.o $(call TGT_PORT_OBJS,$(1)) \
                         $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/tv_corrupt.elf: $(call TGT_TV_OBJS,$(1)) $(TGT)/$(1)/tv_data_corrupt.o $(call TGT_PORT_OBJS,$(1)) \
                            $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/ins_replay.elf: $(call TGT_INSR_OBJS,$(1)) $(TGT)/$(1)/ins_replay_data.o $(call TGT_PORT_OBJS,$(1)) \
                            $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/ins_replay_corrupt.elf: $(call TGT_INSR_OBJS,$(1)) $(TGT)/$(1)/ins_replay_data_corrupt.o \
                                    $(call TGT_PORT_OBJS,$(1)) $(BUILD)/lib-$(1)/libse23.a \
                                    port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/walk_replay.elf: $(call TGT_WALK_OBJS,$(1)) $(TGT)/$(1)/walk_replay_data.o \
                             $(call TGT_PORT_OBJS,$(1)) $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/walk_replay_corrupt.elf: $(call TGT_WALK_OBJS,$(1)) $(TGT)/$(1)/walk_replay_data_corrupt.o \
                                     $(call TGT_PORT_OBJS,$(1)) $(BUILD)/lib-$(1)/libse23.a \
                                     port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/drive_replay.elf: $(call TGT_DRIVE_OBJS,$(1)) $(TGT)/$(1)/drive_replay_data.o \
                              $(call TGT_PORT_OBJS,$(1)) $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/drive_replay_corrupt.elf: $(call TGT_DRIVE_OBJS,$(1)) $(TGT)/$(1)/drive_replay_data_corrupt.o \
                                      $(call TGT_PORT_OBJS,$(1)) $(BUILD)/lib-$(1)/libse23.a \
                                      port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -u _printf_float -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/footprint_%.o: tools/target/footprint_main.c $(LIB_HDRS) | $(TGT)/$(1)/port
	$(ARM_CC) $(2) $(TGT_CFLAGS) -DSE23_CFG_DOUBLE=$(3) \
	    -DFOOTPRINT=$$(TGT_FOOTPRINT_$$*) -c $$< -o $$@
$(TGT)/$(1)/footprint_%.elf: $(TGT)/$(1)/footprint_%.o $(call TGT_PORT_OBJS,$(1)) \
                             $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o %.a,$$^) -lm -o $$@
$(TGT)/$(1)/port_selftest.elf: $(TGT)/$(1)/port_selftest.o $(call TGT_PORT_OBJS,$(1)) \
                               port/cortex-m/sections.ld port/cortex-m/$(TGT_BOARD_$(1)).ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o,$$^) -lm -o $$@
endef
$(eval $(call tgt_variant,m4f-float,$(M4F_FLAGS),0))
$(eval $(call tgt_variant,m7-double,$(M7_FLAGS),1))

# The footprint images (tools/target/footprint_main.c): linked, never run.
TGT_FOOTPRINT_none := 0
TGT_FOOTPRINT_kernels := 1
TGT_FOOTPRINT_filter := 2
TGT_FOOTPRINTS := none kernels filter

TGT_RUN_IMAGES := port_selftest tv_test ins_replay walk_replay drive_replay
TGT_IMAGES := $(foreach v,$(TGT_VARIANTS),$(foreach i,$(TGT_RUN_IMAGES) tv_corrupt ins_replay_corrupt \
                walk_replay_corrupt drive_replay_corrupt,\
                $(TGT)/$(v)/$(i).elf))

target: $(TGT_IMAGES)

# Runs every image of both boards; fails if any exits non-zero.
test-target: target
	@fail=0; $(foreach v,$(TGT_VARIANTS),$(foreach i,$(TGT_RUN_IMAGES),\
	  $(QEMU_RUN) $(TGT_BOARD_$(v)) $(TGT)/$(v)/$(i).elf || fail=1;)) exit $$fail

# The same self-test on the host with the POSIX port.
.PHONY: test-port-posix
$(TGT)/host/port_selftest: tests/target/port_selftest.c port/posix/se23_port.c port/se23_port.h
	mkdir -p $(@D)
	$(CC) $(WARN) -O2 -Iinclude -Iport $(filter %.c,$^) -o $@
test-port-posix: $(TGT)/host/port_selftest
	$<

# The runner's own test: the image built from vectors with one corrupted
# expected value (TGT_CORRUPT) must report exactly one failure.
.PHONY: test-target-corrupt
test-target-corrupt: target
	@fail=0; $(foreach v,$(TGT_VARIANTS),\
	  $(QEMU_RUN) $(TGT_BOARD_$(v)) $(TGT)/$(v)/tv_corrupt.elf; rc=$$?; \
	  if [ $$rc -eq 1 ]; then echo "$(v): corrupted vector detected (exit 1, as required)"; \
	  else echo "$(v): corrupted vector gave exit $$rc, expected 1"; fail=1; fi;) exit $$fail

# The replay's own test: the image built from a reference with three
# perturbed values (a position, a counter, a detector threshold;
# gen_ins_replay --corrupt) must report exactly those three checks failed.
.PHONY: test-target-ins-corrupt
test-target-ins-corrupt: target
	@fail=0; $(foreach v,$(TGT_VARIANTS),\
	  $(QEMU_RUN) $(TGT_BOARD_$(v)) $(TGT)/$(v)/ins_replay_corrupt.elf; rc=$$?; \
	  if [ $$rc -eq 3 ]; then echo "$(v): perturbed reference detected (exit 3, as required)"; \
	  else echo "$(v): perturbed reference gave exit $$rc, expected 3"; fail=1; fi;) exit $$fail

# The walk replay's own test: the image built from a reference with three
# perturbed values (a position, a counter, one sample's stance flag;
# gen_walk_replay --corrupt) must report exactly those three checks failed.
.PHONY: test-target-walk-corrupt
test-target-walk-corrupt: target
	@fail=0; $(foreach v,$(TGT_VARIANTS),\
	  $(QEMU_RUN) $(TGT_BOARD_$(v)) $(TGT)/$(v)/walk_replay_corrupt.elf; rc=$$?; \
	  if [ $$rc -eq 3 ]; then echo "$(v): perturbed walk reference detected (exit 3, as required)"; \
	  else echo "$(v): perturbed walk reference gave exit $$rc, expected 3"; fail=1; fi;) exit $$fail

# The drive replay's own test: the image built from a reference with three
# perturbed values (a position, a counter, one fix's verdict;
# gen_drive_replay --corrupt) must report exactly those three checks failed.
.PHONY: test-target-drive-corrupt
test-target-drive-corrupt: target
	@fail=0; $(foreach v,$(TGT_VARIANTS),\
	  $(QEMU_RUN) $(TGT_BOARD_$(v)) $(TGT)/$(v)/drive_replay_corrupt.elf; rc=$$?; \
	  if [ $$rc -eq 3 ]; then echo "$(v): perturbed drive reference detected (exit 3, as required)"; \
	  else echo "$(v): perturbed drive reference gave exit $$rc, expected 3"; fail=1; fi;) exit $$fail

# Fixtures the gates must reject (tests/target/gate_fixtures), compiled like
# the M4F float library: $(TGT)/gate-fixtures/<name>/<name>.o (+ .su, .ci).
TGT_FIXTURES := bad_symbols bad_vla bad_recursion
.PHONY: gate-fixtures
gate-fixtures: $(foreach f,$(TGT_FIXTURES),$(TGT)/gate-fixtures/$(f)/$(f).o)
define tgt_fixture
$(TGT)/gate-fixtures/$(1)/$(1).o: tests/target/gate_fixtures/$(1).c
	mkdir -p $$(@D)
	cd $$(@D) && $(ARM_CC) $(M4F_FLAGS) $(ARM_CFLAGS) -std=c99 -O2 -fstack-usage \
	    -c $(CURDIR)/$$< -o $(1).o
endef
$(foreach f,$(TGT_FIXTURES),$(eval $(call tgt_fixture,$(f))))

# The Cortex-M port's options header (port/cortex-m/se23_port_opts.h) must
# compile with the library's strict flags and replace every sqrt call.
.PHONY: port-opts
port-opts: $(call lib_objs,$(TGT)/m4f-float/opts) $(call lib_objs,$(TGT)/m7-double/opts)
	@! arm-none-eabi-nm -u $^ | grep -Ew 'sqrtf?' || \
	    { echo "sqrt still called with the port's options"; exit 1; }
	@echo "port-opts: $(words $^) objects, no sqrt/sqrtf call"
PORT_OPTS_CFLAGS := $(filter-out -fstack-usage,$(LIB_CFLAGS)) -Iport/cortex-m \
                    -DSE23_CFG_OPTS_FILE='"se23_port_opts.h"'
$(call lib_obj_rules,$(TGT)/m4f-float/opts,$(ARM_CC) $(PORT_OPTS_CFLAGS) $(M4F_FLAGS) \
    -DSE23_CFG_DOUBLE=0 -c $$< -o $$@)
$(call lib_obj_rules,$(TGT)/m7-double/opts,$(ARM_CC) $(PORT_OPTS_CFLAGS) $(M7_FLAGS) \
    -DSE23_CFG_DOUBLE=1 -c $$< -o $$@)
$(call lib_objs,$(TGT)/m4f-float/opts) $(call lib_objs,$(TGT)/m7-double/opts): \
    port/cortex-m/se23_port_opts.h

# Gates on the library objects built for the target (also run one by one by
# tests/check.d/45-gates.sh): no soft double in the float build, no heap and
# no stdio in either, worst-case stack per public function and code size
# against tests/target/budgets/.
PY3 ?= /usr/bin/python3
TGT_BUDGETS := tests/target/budgets
.PHONY: gates-target
gates-target: cross target footprint-images
	$(PY3) tools/target/symbol_gate.py soft-double $(BUILD)/lib-m4f-float/*.o
	$(foreach v,$(TGT_VARIANTS),$(PY3) tools/target/symbol_gate.py heap $(BUILD)/lib-$(v)/*.o &&) true
	$(foreach v,$(TGT_VARIANTS),$(PY3) tools/target/symbol_gate.py stdio $(BUILD)/lib-$(v)/*.o &&) true
	$(foreach v,$(TGT_VARIANTS),$(PY3) tools/target/stack_gate.py $(BUILD)/lib-$(v) \
	    $(TGT)/$(v)/tv_test.elf,$(TGT)/$(v)/ins_replay.elf $(TGT_BUDGETS)/stack.txt $(v) &&) true
	$(foreach v,$(TGT_VARIANTS),$(PY3) tools/target/size_gate.py $(BUILD)/lib-$(v)/libse23.a \
	    $(TGT_BUDGETS)/size.txt $(v) &&) true
	$(foreach v,$(TGT_VARIANTS),$(PY3) tools/target/footprint.py $(v) \
	    $(foreach i,kernels filter none,$(TGT)/$(v)/footprint_$(i).map) &&) true

# The footprint images of both variants.
.PHONY: footprint-images
footprint-images: $(foreach v,$(TGT_VARIANTS),$(foreach i,$(TGT_FOOTPRINTS),$(TGT)/$(v)/footprint_$(i).elf))

# Instruction counts (make bench-target): the benchmark image of each
# variant (tools/target/bench_main.c) under QEMU with the counting plugin
# tools/target/insn_count.c; table printed and kept in $(TGT)/bench.md.
TGT_PLUGIN := $(TGT)/insn_count.so
$(TGT_PLUGIN): tools/target/insn_count.c
	mkdir -p $(@D)
	$(CC) -std=c11 -Wall -Wextra -Wpedantic -Werror -O2 -shared -fPIC $< -o $@
define tgt_bench
$(TGT)/$(1)/bench/%.o: tools/target/%.c $(wildcard tools/target/*.h) tests/target/tv.h $(LIB_HDRS)
	mkdir -p $$(@D)
	$(ARM_CC) $(2) $(TGT_CFLAGS) -Itests/target -Itools/target -DSE23_CFG_DOUBLE=$(3) -c $$< -o $$@
$(TGT)/$(1)/bench.elf: $(patsubst %,$(TGT)/$(1)/bench/%.o,bench_main bench_marks bench_steps) \
                       $(call TGT_TV_LIB_OBJS,$(1)) $(TGT)/$(1)/tv_data.o \
                       $(call TGT_PORT_OBJS,$(1)) $(BUILD)/lib-$(1)/libse23.a port/cortex-m/sections.ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    $$(filter %.o %.a,$$^) -lm -o $$@
endef
$(eval $(call tgt_bench,m4f-float,$(M4F_FLAGS),0))
$(eval $(call tgt_bench,m7-double,$(M7_FLAGS),1))

.PHONY: bench-target
bench-target: $(TGT_PLUGIN) $(foreach v,$(TGT_VARIANTS),$(TGT)/$(v)/bench.elf)
	$(PY3) tools/target/bench.py $(TGT_PLUGIN) \
	    $(foreach v,$(TGT_VARIANTS),$(v)=$(TGT_BOARD_$(v))=$(TGT)/$(v)/bench.elf) \
	    --out $(TGT)/bench.md

# The tables of tools/doc/pages/cortex-m*.md (size, stack per function,
# instructions per call, the hot path, what a firmware links), written into
# $(TGT)/report-*.md and pasted into the pages by make doc-tables.
.PHONY: report-target
report-target: bench-target target footprint-images
	@$(PY3) tools/target/report.py $(BUILD)
