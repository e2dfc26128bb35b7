#!/bin/sh
# Self-test of se23-drive-import and se23-drive (tools/drive) on tiny
# fabricated drives, a few seconds each:
#  - rtklib format (IMU CSV in g and deg/s with a ms tick, RTKLIB time-tag
#    file, .pos with Q=1, Q=2, Q=5 epochs) with one malformed IMU row, one
#    repeated tick, one malformed .pos row: the counters, the time map, the
#    outage drop, the sidecar;
#  - ublox format, plain and gzip, with one non-finite IMU row and one
#    repeated timestamp;
#  - refusals: accelerometer in the wrong unit (both formats), a missing
#    file, a file that is no time-tag file, bad usage; none leaves a log;
#  - se23-drive on a nav log with known errors (se23-drive-synth): the
#    aided error, the NEES, the outage's end error and %, a bound's exit 1.
#
#   sh tools/drive/selftest.sh HARNESS_BUILD_DIR
#
# Exits 1 at the first failed check, after saying which.
set -eu
H=$1
BIN="$H/bin"
W="$H/drive-selftest"
rm -rf "$W"
mkdir -p "$W"
fail() {
    echo "drive-selftest: FAIL: $*" >&2
    exit 1
}
# expect NAME VALUE FILE: the counter line "  NAME VALUE" is in FILE
expect() {
    grep -q "^  $1 $2\$" "$3" || fail "$3: expected $1 = $2, got: $(grep "^  $1 " "$3" || echo none)"
}
# run_rc EXPECTED_RC LOGFILE CMD...: runs CMD with output into LOGFILE
run_rc() {
    want=$1
    out=$2
    shift 2
    rc=0
    "$@" >"$out" 2>&1 || rc=$?
    [ "$rc" = "$want" ] || { cat "$out" >&2; fail "exit status $rc, expected $want: $*"; }
}

/usr/bin/python3 - "$W" <<'EOF'
import gzip, os, shutil, struct, sys
w = sys.argv[1]
R = os.path.join(w, "rtk"); U = os.path.join(w, "ublox"); os.makedirs(R); os.makedirs(U)

def rtk_imu(path, g_scale):
    # 800 samples at 10 ms ticks: 3 s at rest (IMU z up), then forward
    # acceleration (IMU x backward); a malformed row and a repeated tick
    lines = []
    for k in range(800):
        tick = 100000 + 10 * k
        ax = 0.0 if k < 300 else -0.1
        jit = 0.001 * ((k * 7) % 5 - 2)
        lines.append("%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%d"
                     % (ax * g_scale, jit * g_scale, (1.0 + jit) * g_scale, jit, -jit, 0.0, tick))
        if k == 399:
            lines.append(lines[-1])                         # repeated tick, same values
        if k == 299:
            lines.append("0.0,abc,1.0,0,0,0,%d" % (tick + 5))  # malformed
    open(path, "w").write("\n".join(lines) + "\n")

rtk_imu(os.path.join(R, "imu.csv"), 1.0)
rtk_imu(os.path.join(R, "imu_ms2.csv"), 9.80665)
# time tags: opened at GPST 1752003261.5 (2025-07-08 19:34:21.5), 8 s of records
with open(os.path.join(R, "imu.csv.tag"), "wb") as f:
    f.write(b"TIMETAG RTKLIB demo5".ljust(60, b"\0"))
    f.write(struct.pack("<IId", 123, 1752003261, 0.5))
    for k in range(81):
        f.write(struct.pack("<II", 100 * k, 100 * k))
open(os.path.join(R, "bad.tag"), "wb").write(b"not a tag file" * 10)
# .pos: 41 epochs at 4 Hz from 19:34:20.000, 1e-5 deg north per epoch
hdr = ("%  GPST                  latitude(deg) longitude(deg)  height(m)   Q  ns   sdn(m)   "
       "sde(m)   sdu(m)  sdne(m)  sdeu(m)  sdun(m) age(s)  ratio    vn(m/s)    ve(m/s)    "
       "vu(m/s)      sdvn     sdve     sdvu    sdvne    sdveu    sdvun\n")
rows = []
for k in range(41):
    s = 20.0 + 0.25 * k
    q = 2 if k in (14, 15) else 5 if k == 20 else 1
    rows.append("2025/07/08 19:34:%06.3f %.7f %.7f %.4f %d 20 0.0100 0.0100 0.0200 0 0 0 0 0 "
                "4.45 0.0 -0.5 0.05 0.05 0.08 0 0 0"
                % (s, 40.0966268 + 1e-5 * k, -105.1474483, 1601.474, q))
    if k == 30:
        rows.append("2025/07/08 19:34:27.600 40.0966268 -105.1474483 1601.4 1 20 0.01")
open(os.path.join(R, "sol.pos"), "w").write(hdr + "\n".join(rows) + "\n")

# ublox: 600 IMU rows at 100 Hz (3 s at rest), GNSS 2 Hz, reference 10 Hz
def ublox(d, a_scale):
    os.makedirs(d, exist_ok=True)
    L = ["t_s,gx_radps,gy_radps,gz_radps,ax_mps2,ay_mps2,az_mps2"]
    for k in range(600):
        t = -0.01 + 0.01 * k
        jit = 0.002 * ((k * 3) % 5 - 2)
        L.append("%.5f,%.5f,%.5f,0.0,%.4f,%.4f,%.4f" % (t, jit, -jit, (0.1 + (0.5 if k >= 300 else 0)) * a_scale,
                                                          -0.2 * a_scale, (9.80 + jit) * a_scale))
        if k == 100:
            L.append(L[-1])                                       # repeated timestamp
        if k == 200:
            L.append("%.5f,nan,0,0,0.1,-0.2,9.8" % (t + 0.005))     # non-finite
    open(os.path.join(d, "imu.csv"), "w").write("\n".join(L) + "\n")
    G = ["t_s,lat_deg,lon_deg,height_m,vn_mps,ve_mps,vd_mps,pos_std_n_m,pos_std_e_m,pos_std_d_m,"
         "vel_std_n_mps,vel_std_e_mps,vel_std_d_mps,heading_rad"]
    for k in range(12):
        G.append("%.3f,%.9f,-79.6887397,110.378,0,0,0,0.5,0.5,0.8,0.2,0.2,0.2,0" % (0.5 * k, 43.479282900 + 1e-6 * k))
    open(os.path.join(d, "gnss.csv"), "w").write("\n".join(G) + "\n")
    P = ["t_s,lat_deg,lon_deg,height_m,vn_mps,ve_mps,vd_mps,heading_rad"]
    for k in range(60):
        P.append("%.3f,%.9f,-79.6887397,110.3,0,0,0,0" % (0.1 * k, 43.479282900 + 2e-7 * k))
    open(os.path.join(d, "reference_position.csv"), "w").write("\n".join(P) + "\n")

ublox(U, 1.0)
ublox(os.path.join(w, "ublox_g"), 1.0 / 9.80665)
gz = os.path.join(w, "ublox_gz"); os.makedirs(gz)
for n in ("imu", "gnss", "reference_position"):
    with open(os.path.join(U, n + ".csv"), "rb") as fi, gzip.open(os.path.join(gz, n + ".csv.gz"), "wb") as fo:
        shutil.copyfileobj(fi, fo)
EOF

R="$W/rtk"
IMP="$BIN/se23-drive-import"

# rtklib: counters, the Q split, an outage
run_rc 0 "$W/rtk.txt" "$IMP" --out "file://$W/rtk.log?mode=w" --axes=-x,y,-z \
    --imu-time-offset -0.125 --outage 2,1 --rtklib "$R/imu.csv" "$R/imu.csv.tag" "$R/sol.pos"
expect imu_rows 800 "$W/rtk.txt"
expect imu_written 798 "$W/rtk.txt"
expect imu_dup_time 1 "$W/rtk.txt"
expect imu_malformed 1 "$W/rtk.txt"
expect gnss_rows 42 "$W/rtk.txt"
expect gnss_malformed 1 "$W/rtk.txt"
expect gnss_valid 40 "$W/rtk.txt"
expect ref_valid 38 "$W/rtk.txt"
grep -q "imu.csv:301: IMU row: a field is not a number" "$W/rtk.txt" ||
    fail "the malformed IMU row's line number is not reported"
grep -q "wrote 798 IMU samples, 36 GNSS fixes (4 dropped in 1 outage(s), 0 without sigma), 38 reference epochs" \
    "$W/rtk.txt" || fail "rtk: written counts: $(grep wrote "$W/rtk.txt")"
grep -q "first_fix_s 0.000000000" "$W/rtk.log.drive" || fail "rtk: sidecar first_fix_s"
grep -q "^outage 2.000000 1.000000" "$W/rtk.log.drive" || fail "rtk: sidecar outage"
grep -q "origin lat 40.096626800 deg, lon -105.147448300 deg, h 1601.474 m" "$W/rtk.txt" ||
    fail "rtk: origin"
# the time map: ticks 100010..107990 (first and last line skipped) onto
# 19:34:21.5 + 0..8 s, minus 0.125 s; t = 0 is 19:34:20 (the first fix)
grep -q "stretched by 1.003764" "$W/rtk.txt" || fail "rtk: tag stretch $(grep stretched "$W/rtk.txt")"
grep -q "span 9.375000000 s" "$W/rtk.txt" || fail "rtk: IMU span $(grep span "$W/rtk.txt")"

# ublox, plain and gzip: the same counts
for d in ublox ublox_gz; do
    run_rc 0 "$W/$d.txt" "$IMP" --out "file://$W/$d.log?mode=w" --ublox "$W/$d"
    expect imu_rows 602 "$W/$d.txt"
    expect imu_written 600 "$W/$d.txt"
    expect imu_dup_time 1 "$W/$d.txt"
    expect imu_nonfinite 1 "$W/$d.txt"
    expect gnss_valid 12 "$W/$d.txt"
    expect ref_valid 60 "$W/$d.txt"
    grep -q "wrote 600 IMU samples, 12 GNSS fixes" "$W/$d.txt" || fail "$d: written counts"
done

# refusals, none leaving a log
run_rc 1 "$W/r1.txt" "$IMP" --out "file://$W/r1.log?mode=w" --rtklib "$R/imu_ms2.csv" \
    "$R/imu.csv.tag" "$R/sol.pos"
grep -q "the accelerometer reads 9.8" "$W/r1.txt" || fail "rtk m/s^2 as g not refused"
run_rc 1 "$W/r2.txt" "$IMP" --out "file://$W/r2.log?mode=w" --ublox "$W/ublox_g"
grep -q "the accelerometer reads 0.1" "$W/r2.txt" || fail "ublox g as m/s^2 not refused"
run_rc 1 "$W/r3.txt" "$IMP" --out "file://$W/r3.log?mode=w" --rtklib "$R/missing.csv" \
    "$R/imu.csv.tag" "$R/sol.pos"
grep -q "cannot read .*missing.csv" "$W/r3.txt" || fail "missing file not reported"
run_rc 1 "$W/r4.txt" "$IMP" --out "file://$W/r4.log?mode=w" --rtklib "$R/imu.csv" \
    "$R/bad.tag" "$R/sol.pos"
grep -q "not an RTKLIB time-tag file" "$W/r4.txt" || fail "bad tag file not refused"
run_rc 1 "$W/r5.txt" "$IMP" --out "file://$W/r5.log?mode=w" --ublox "$W/nodir"
run_rc 2 "$W/r6.txt" "$IMP" --rtklib "$R/imu.csv" "$R/imu.csv.tag" "$R/sol.pos"
run_rc 2 "$W/r7.txt" "$IMP" --out "file://$W/r7.log?mode=w" --ublox "$W/ublox" --outage 5
for k in 1 2 3 4 5 7; do
    [ ! -e "$W/r$k.log" ] || fail "refused import r$k left a log behind"
done

# se23-drive on known errors: bias (0.3, 0.4) m, 2 m/s east in the outage
run_rc 0 "$W/synth.txt" "$BIN/se23-drive-synth" --out "file://$W/nav.log?mode=w" \
    --bias 0.3,0.4,0 --drift 2 --sigma 0.1 "$W/rtk.log"
run_rc 0 "$W/score.txt" "$BIN/se23-drive" --min-distance 1 --settle 0 --csv "$W/score.csv" \
    --max-aided-h95 0.6 "$W/rtk.log" "$W/nav.log"
grep -q "horizontal error median 0.500 m, 95% 0.500 m, max 0.500 m" "$W/score.txt" ||
    fail "aided error: $(grep 'with GNSS (' "$W/score.txt")"
# NEES = 0.25 / (0.1^2 + 0.01^2) = 24.75
grep -q "NEES (3 dof) mean 24.75" "$W/score.txt" || fail "NEES: $(grep NEES "$W/score.txt")"
# outage 2..3 s: last reference epoch at 2.75 s, error (0.3, 0.4 + 1.5) -> 1.924 m,
# over 3 reference steps of 1e-5 deg (3.336 m): 57.7 %
awk -F, 'NR == 2 { ok = ($5 > 3.33 && $5 < 3.34 && $6 > 1.923 && $6 < 1.925 &&
                         $7 > 57.6 && $7 < 57.8 && $4 == 0.75) }
         END { exit !ok }' "$W/score.outages.csv" ||
    fail "outage row: $(sed -n 2p "$W/score.outages.csv")"
run_rc 1 "$W/bound.txt" "$BIN/se23-drive" --settle 0 --max-aided-h95 0.4 "$W/rtk.log" "$W/nav.log"
grep -q "FAIL: 95% horizontal error with GNSS 0.500 m > 0.400 m" "$W/bound.txt" ||
    fail "bound not reported"
run_rc 1 "$W/bound2.txt" "$BIN/se23-drive" --min-distance 1 --max-outage-pct-len 1:50 \
    "$W/rtk.log" "$W/nav.log"
run_rc 2 "$W/usage.txt" "$BIN/se23-drive" "$W/rtk.log"
echo "drive-selftest: ok (rtklib and ublox imports, counters, refusals, se23-drive on known errors)"
