# se23 LCM harness (tools/lcm, tools/sim, tools/ins, tools/report).
# Included by the top-level Makefile (BUILD, CC, WARN, JOBS come from there).
#
#   make harness     se23-sim, se23-ins, se23-report, se23-corrupt, se23-simcheck,
#                    se23-import (CSV IMU log -> LCM log), se23-importcheck
#   make demo        60 s UAV flight, MEMS IMU 200 Hz, Earth rotation, GNSS 5 Hz,
#                    sim -> LCM -> se23-ins -> LCM -> report + plots
#   make demo-live   the same over udpm:// in a private network namespace
#   make soak        10^7 filter steps per precision, aided and unaided (se23-soak)
#   make demo-walk   a real foot-mounted walk (CSV) through the library's filter:
#                    loop-closure error, distance, stance phases, plots
#   make walk CSV=path [IMPORT="..."] [LAT=deg]  the same for any recording
#   make walk-corpus DIR=folder  every recording of a folder, one table
#   make walk-misalign  the walk's closure against a misalignment of the
#                    accelerometer's triad (MISALIGN="rx,ry,rz ..." degrees)
#   make walk-sim    the walk's simulated twin (se23-sim --scenario walk) with
#                    and without such a misalignment (MISALIGN=..., SEED=N)
#   make bench-ins   se23-ins throughput on a recorded log of 1.2 M IMU samples
#   make demo-drive  a real car drive (roof IMU, RTK GNSS) through the library's
#                    car preset: error against RTK truth, GNSS outages of 10/30/60 s
#                    with and without the non-holonomic constraint, double and
#                    float, plots (tools/drive/)
#   make drive-corpus DIR=folder  the same outage test on every drive of a folder

H := $(BUILD)/harness
H_GEN := $(H)/gen
H_BIN := $(H)/bin
LCM_TYPES := $(sort $(wildcard tools/lcm/*.lcm))
LCM_GEN_C := $(patsubst tools/lcm/%.lcm,$(H_GEN)/se23lcm_%.c,$(LCM_TYPES))
LCM_CFLAGS := $(shell pkg-config --cflags lcm 2>/dev/null)
LCM_LIBS := $(shell pkg-config --libs lcm 2>/dev/null || echo -llcm)

# Generated C is clean under -Wall only (TOOLCHAIN.md): its own object set,
# relaxed warnings; our code sees its headers as system headers.
H_GEN_CFLAGS := -std=c99 -O2 -Wall -I$(H_GEN) $(LCM_CFLAGS)
H_CFLAGS := $(WARN) -Wshadow -Wstrict-prototypes -Wmissing-prototypes -O2 -g \
            -Iinclude -isystem $(H_GEN) $(LCM_CFLAGS)

H_COMMON := tools/lcm/harness.c tools/lcm/ldmath.c
H_SIM_SRCS := $(wildcard tools/sim/*.c) $(H_COMMON)
H_INS_SRCS := $(wildcard tools/ins/*.c) $(H_COMMON) tools/lcm/logfile.c
H_REPORT_SRCS := $(wildcard tools/report/*.c) $(H_COMMON) tools/lcm/logfile.c
H_WALK_SRCS := tools/walk/main.c tools/report/logread.c tools/report/metrics.c $(H_COMMON) \
               tools/lcm/logfile.c
H_CORRUPT_SRCS := tools/lcm/corrupt.c tools/lcm/corrupt_framing.c tools/lcm/corrupt_nav.c \
                  tools/lcm/logfile.c $(H_COMMON)
H_SIMCHECK_SRCS := tools/lcm/simcheck.c tools/lcm/logfile.c $(H_COMMON)
H_IMPORT_SRCS := tools/import/main.c tools/import/csv.c tools/import/row.c \
                 tools/import/hygiene.c tools/import/gyrocheck.c $(H_COMMON)
H_IMPORTCHECK_SRCS := tools/import/check.c tools/lcm/logfile.c $(H_COMMON)
H_HDRS := $(wildcard tools/lcm/*.h tools/sim/*.h tools/ins/*.h tools/report/*.h \
                     tools/import/*.h) $(LIB_HDRS)
H_LIB := $(BUILD)/lib-host-double/libse23.a
h_objs = $(patsubst %.c,$(H)/obj/%.o,$(1))

include tools/drive/drive.mk

.PHONY: harness demo demo-live demo-walk walk walk-corpus walk-misalign walk-sim bench-ins soak \
        demo-drive drive-corpus

harness: $(H_BIN)/se23-sim $(H_BIN)/se23-ins $(H_BIN)/se23-report $(H_BIN)/se23-corrupt \
         $(H_BIN)/se23-simcheck $(H_BIN)/se23-walk $(H_BIN)/se23-ins-float \
         $(H_BIN)/se23-import $(H_BIN)/se23-importcheck $(H_BIN)/se23-soak $(H_BIN)/se23-soak-float \
         drive-tools

$(H_GEN)/.stamp: $(LCM_TYPES)
	@mkdir -p $(H_GEN)
	lcm-gen -c --c-cpath $(H_GEN) --c-hpath $(H_GEN) $(LCM_TYPES)
	@touch $@
$(LCM_GEN_C): $(H_GEN)/.stamp ;

$(H)/gen-obj/%.o: $(H_GEN)/%.c $(H_GEN)/.stamp
	@mkdir -p $(dir $@)
	$(CC) $(H_GEN_CFLAGS) -c $< -o $@
$(H)/libse23lcm.a: $(patsubst $(H_GEN)/%.c,$(H)/gen-obj/%.o,$(LCM_GEN_C))
	rm -f $@ && ar rcs $@ $^

# se23-ins once more on the float library (the Cortex-M4F precision), for
# the float figures of make demo-walk.
$(H)/obj-float/%.o: %.c $(H_HDRS) $(H_GEN)/.stamp
	@mkdir -p $(dir $@)
	$(CC) $(H_CFLAGS) -DSE23_CFG_DOUBLE=0 -c $< -o $@
$(H_BIN)/se23-ins-float: $(patsubst %.c,$(H)/obj-float/%.o,$(H_INS_SRCS)) $(H)/libse23lcm.a \
                         $(BUILD)/lib-host-float/libse23.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm

# se23-soak, double and float (tools/soak).
H_SOAK_SRCS := tools/soak/soak.c $(H_COMMON)
$(H_BIN)/se23-soak: $(call h_objs,$(H_SOAK_SRCS)) $(H_LIB)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-soak-float: $(patsubst %.c,$(H)/obj-float/%.o,$(H_SOAK_SRCS)) \
                          $(BUILD)/lib-host-float/libse23.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm

$(H)/obj/%.o: %.c $(H_HDRS) $(H_GEN)/.stamp
	@mkdir -p $(dir $@)
	$(CC) $(H_CFLAGS) -c $< -o $@

$(H_BIN)/se23-sim: $(call h_objs,$(H_SIM_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-ins: $(call h_objs,$(H_INS_SRCS)) $(H)/libse23lcm.a $(H_LIB)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-walk: $(call h_objs,$(H_WALK_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-report: $(call h_objs,$(H_REPORT_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-corrupt: $(call h_objs,$(H_CORRUPT_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-simcheck: $(call h_objs,$(H_SIMCHECK_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-import: $(call h_objs,$(H_IMPORT_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm
$(H_BIN)/se23-importcheck: $(call h_objs,$(H_IMPORTCHECK_SRCS)) $(H)/libse23lcm.a
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LCM_LIBS) -lm

demo:
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@sh tools/lcm/demo.sh $(H)

soak: harness
	@sh tools/soak/table.sh run $(H_BIN) $(BUILD)/soak/soak.md --steps 10000000 --check-every 1000000

demo-walk:
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@sh tools/walk/demo-walk.sh $(H)

# make walk CSV=path [IMPORT="se23-import options"] [LAT=deg]: any
# foot-mounted recording through the pedestrian filter (tools/walk/walk.sh).
walk:
	@test -n "$(CSV)" || { echo "make walk: give CSV=path (and IMPORT=\"se23-import options\")" >&2; exit 2; }
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@IMPORT="$(IMPORT)" LAT="$(LAT)" sh tools/walk/walk.sh $(H) $(H)/walk-$(notdir $(basename $(CSV))) "$(CSV)"

# make walk-corpus DIR=folder: every recording of the folder through the
# pedestrian filter, one table (tools/walk/corpus.py).
walk-corpus:
	@test -n "$(DIR)" || { echo "make walk-corpus: give DIR=folder of recordings" >&2; exit 2; }
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@/usr/bin/python3 tools/walk/corpus.py --bin $(H_BIN) --run $(H)/walk-corpus \
	    --summary $(H)/walk-corpus.csv --plot $(H)/walk-corpus.png $(DIR)

demo-drive:
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@sh tools/drive/demo-drive.sh $(H)

drive-corpus:
	@test -n "$(DIR)" || { echo "make drive-corpus: give DIR=folder of drives" >&2; exit 2; }
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@/usr/bin/python3 tools/drive/corpus.py --bin $(H_BIN) --work $(H)/drive-corpus \
	    --summary $(H)/drive-corpus.csv $(FLOAT:1=--float) $(DIR)

walk-misalign:
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@INS_OPTS="$(INS_OPTS)" sh tools/walk/misalign-sweep.sh $(H) $(MISALIGN)

walk-sim:
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@sh tools/walk/sim-walk.sh $(H) $(MISALIGN)

demo-live:
	@sh tools/install-deps.sh $(BUILD)
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@sh tools/lcm/live.sh $(H)

bench-ins:
	@$(MAKE) -s --no-print-directory harness BUILD=$(BUILD)
	@sh tools/lcm/bench-ins.sh $(H)
