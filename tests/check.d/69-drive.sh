# Real car drives (issue 35; tools/drive/, tools/doc/pages/drives.md). The
# importer and the report on fabricated drives (tools/drive/selftest.sh:
# counters, time map, outages, refusals of malformed and wrongly-scaled
# files, the report's figures on a nav log with known errors). Then the
# shipped RTK drive end to end (make demo-drive: every run of the table in
# double and in float), its figures held within 25 % of those measured
# (tools/doc/pages/drives.md, this machine): with every fix the median
# horizontal error against the RTK truth 0.011 m (bound 0.014); the median
# end error of the outages with the non-holonomic constraint 3.47 / 1.78 /
# 1.69 % of the distance for 10 / 30 / 60 s (bounds 4.3 / 2.2 / 2.1); float
# within 10 % of double on each. Without the constraint the 30 s outages'
# median is 13.9 %: the bound that holds with it must fail. One aided run
# under valgrind. The programs are built by 60-harness.sh.
DB="$BUILD/harness/bin"
DR="$BUILD/harness/drive"
check drive-selftest sh tools/drive/selftest.sh "$BUILD/harness"
check drive-shipped sh -c 'sh tools/drive/demo-drive.sh "$1" >/dev/null &&
    /usr/bin/python3 tools/drive/summary.py --max-pct 10:4.3,30:2.2,60:2.1 \
        --max-float-ratio 0.1 "$2" &&
    "$3/se23-drive" --lever 0,-0.05,0 --max-aided-h50 0.014 --max-nees-beyond 0.13 "$2/aided.log" \
        "$2/aided-double.log" && "$3/se23-drive" --lever 0,-0.05,0 --max-aided-h50 0.014 \
        "$2/aided.log" "$2/aided-float.log"' sh "$BUILD/harness" "$DR" "$DB"
# shellcheck disable=SC2016 # expanded by the inner shell
check drive-no-nhc-fails-bound sh -c '! "$1/se23-drive" --lever 0,-0.05,0 \
    --max-outage-pct 2.2 "$2/o30.log" "$2/o30-none-double.log"' sh "$DB" "$DR"
d_valgrind() {
    . tools/drive/rtklibexplorer-0708.conf
    $VALGRIND --suppressions=tools/lcm/valgrind-lcm.supp "$DB/se23-ins" --preset car \
        --lat "$LAT" --height "$HEIGHT" --mount "$MOUNT" --lever "$LEVER" --nav-rate 10 \
        --in "file://$DR/aided.log?speed=0" --out "file://$DR/aided-vg.log?mode=w"
}
check drive-valgrind d_valgrind
