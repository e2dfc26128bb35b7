# Paper reproductions (tools/doc/pages/paper.md). Included by the top-level Makefile (BUILD, CC, WARN come from
# there); host only, double build of the library.
#
#   make paper-table       the paper's Table "Higher-order errors for a
#                          low-cost IMU", full size (600 s, 200 fresh bias
#                          draws per factor, two draw schemes, ~31 s of
#                          CPU), plus the trajectory figure
#   make paper-montecarlo  the paper's Figure on Monte Carlo clouds: mean NEES
#                          of the exponential model and of a standard EKF at
#                          four noise levels, endpoint clouds to a PNG
#   make paper             both
#
# The tools reuse the tests' seeded generator and double statistics
# (tests/support/se23_rng.c, tests/support/gauss_test.h; no test framework).
# tests/check.d/70-paper.sh runs both on a reduced size in `make check`.

PAPER := $(BUILD)/paper
PAPER_LIB := $(BUILD)/lib-host-double/libse23.a
PAPER_CFLAGS := $(WARN) -Wshadow -Wstrict-prototypes -Wmissing-prototypes -O2 \
                -Iinclude -Itests/support -DSE23_CFG_DOUBLE=1
PAPER_LIBS := -lm
PAPER_SUPPORT := tests/support/se23_rng.c
PAPER_SUPPORT_H := tests/support/se23_rng.h tests/support/gauss_test.h
PAPER_TABLE_SRCS := tools/paper_table/table.c tools/paper_table/rows.c tools/paper_table/uav.c
PAPER_MC_SRCS := tools/montecarlo/montecarlo.c tools/montecarlo/ekf.c
PAPER_PY := /usr/bin/python3

.PHONY: paper paper-bins paper-table paper-montecarlo

paper-bins: $(PAPER)/se23-paper-table $(PAPER)/se23-montecarlo

$(PAPER)/se23-paper-table: $(PAPER_TABLE_SRCS) tools/paper_table/uav.h tools/paper_table/rows.h tools/montecarlo/paper_tool.h $(PAPER_SUPPORT) \
                           $(PAPER_SUPPORT_H) $(PAPER_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(PAPER_CFLAGS) $(PAPER_TABLE_SRCS) $(PAPER_SUPPORT) $(PAPER_LIB) $(PAPER_LIBS) -o $@

$(PAPER)/se23-montecarlo: $(PAPER_MC_SRCS) tools/montecarlo/ekf.h tools/montecarlo/paper_tool.h $(PAPER_SUPPORT) \
                          $(PAPER_SUPPORT_H) $(PAPER_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(PAPER_CFLAGS) $(PAPER_MC_SRCS) $(PAPER_SUPPORT) $(PAPER_LIB) $(PAPER_LIBS) -o $@

paper-table: $(PAPER)/se23-paper-table
	$(PAPER)/se23-paper-table --traj $(PAPER)/uav-trajectory.csv
	$(PAPER_PY) tools/paper_table/plot_traj.py $(PAPER)/uav-trajectory.csv \
	    $(PAPER)/uav-trajectory.png
	@echo "figure: $(PAPER)/uav-trajectory.png"

paper-montecarlo: $(PAPER)/se23-montecarlo
	$(PAPER)/se23-montecarlo --sweep --csv $(PAPER)/clouds.csv
	@echo
	$(PAPER)/se23-montecarlo --gyro 0.05,0.05,0.05 --accel 0.5 --sweep
	$(PAPER_PY) tools/montecarlo/plot_clouds.py $(PAPER)/clouds.csv $(PAPER)/montecarlo.png \
	    "2000 runs, 10 s at 100 Hz, 50 m/s, gyro 0.1 rad/s/sqrt(Hz), accel 0.05 m/s^2/sqrt(Hz)"
	@echo "figure: $(PAPER)/montecarlo.png"

paper: paper-table paper-montecarlo
