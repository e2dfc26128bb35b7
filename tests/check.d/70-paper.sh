# Paper reproductions (tools/paper.mk), reduced size:
#  - the Table "Higher-order errors for a low-cost IMU" on 120 s of the UAV
#    trajectory with 32 fresh bias draws per factor: in velocity RMS the
#    paper's proposed correction (basic B_k) must be no worse than the
#    classical pipeline of Forster et al. at T = 1 s, 10 s and 60 s, the
#    exact B_k no worse than the basic one at 1 s, and in position at 1 s the
#    paper's correction on the Deltas of its own eq. backtofuture
#    (se23_imu_increment_paper) no worse than on the exact Deltas (tools/doc/pages/paper.md
#    has the full table and which increment each row uses). On the first 60 s
#    alone the proposed correction loses at 60 s, and the same check must
#    fail there (the check can fail);
#  - the Monte Carlo of the paper's Figure at moderate noise: the mean NEES
#    of the concentrated Gaussian inside the 95% interval of chi^2_9 for 2000
#    runs, the standard EKF's above it (the check can fail);
#  - the cloud plot renders.
PAPER_DIR="$BUILD/paper"
check paper-build make -s paper-bins BUILD="$BUILD"
check paper-table-reduced "$PAPER_DIR/se23-paper-table" --duration 120 --draws 32 --check
check paper-table-check-can-fail sh -c '! "$1" --duration 60 --draws 32 --check' sh \
    "$PAPER_DIR/se23-paper-table"
check paper-montecarlo-nees "$PAPER_DIR/se23-montecarlo" --gyro 0.05,0.05,0.05 --accel 0.5 \
    --runs 2000 --check
paper_plot() {
    "$PAPER_DIR/se23-montecarlo" --runs 500 --csv "$PAPER_DIR/check-clouds.csv" &&
        /usr/bin/python3 tools/montecarlo/plot_clouds.py "$PAPER_DIR/check-clouds.csv" \
            "$PAPER_DIR/check-clouds.png" && [ -s "$PAPER_DIR/check-clouds.png" ]
}
check paper-montecarlo-plot paper_plot
