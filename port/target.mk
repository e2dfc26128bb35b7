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

TGT_VARIANTS := m4f-float m7-double
TGT_BOARD_m4f-float := mps2-an386
TGT_BOARD_m7-double := mps2-an500

.PHONY: target test-target

# $(call tgt_variant,variant,arch flags,SE23_CFG_DOUBLE)
define tgt_variant
$(TGT)/$(1)/port/%.o: port/cortex-m/%.S | $(TGT)/$(1)/port
	$(ARM_CC) $(2) -c $$< -o $$@
$(TGT)/$(1)/port/%.o: port/cortex-m/%.c port/se23_port.h | $(TGT)/$(1)/port
	$(ARM_CC) $(2) $(TGT_CFLAGS) -DSE23_CFG_DOUBLE=$(3) -c $$< -o $$@
$(TGT)/$(1)/%.o: tests/target/%.c $(LIB_HDRS) $(wildcard tests/target/*.h) | $(TGT)/$(1)/port
	$(ARM_CC) $(2) $(TGT_CFLAGS) -Itests/target -I$(TGT)/$(1) \
	    -DSE23_CFG_DOUBLE=$(3) -c $$< -o $$@
$(TGT)/$(1)/port:
	mkdir -p $$@
$(TGT)/$(1)/port_selftest.elf: $(TGT)/$(1)/port_selftest.o $(call TGT_PORT_OBJS,$(1)) \
                               port/cortex-m/sections.ld port/cortex-m/$(TGT_BOARD_$(1)).ld
	$(ARM_CC) $(2) $(TGT_LDFLAGS) -Tport/cortex-m/$(TGT_BOARD_$(1)).ld \
	    -Wl,-Map,$$(@:.elf=.map) $$(filter %.o,$$^) -lm -o $$@
endef
$(eval $(call tgt_variant,m4f-float,$(M4F_FLAGS),0))
$(eval $(call tgt_variant,m7-double,$(M7_FLAGS),1))

TGT_RUN_IMAGES := port_selftest
TGT_IMAGES := $(foreach v,$(TGT_VARIANTS),$(foreach i,$(TGT_RUN_IMAGES),$(TGT)/$(v)/$(i).elf))

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
