# Soak (tools/soak, se23-soak and se23-soak-float; built by 60-harness.sh):
# the library's filter over 10^6 steps (83 min at 200 Hz) of bounded random
# motion, aided (GNSS 1 Hz) and unaided, both precisions: no non-finite
# value, R in SO(3) within SE23_CFG_ROT_TOL, P positive semidefinite to
# rounding, no failed step (the program's exit status); and the same seed
# twice gives the same final-state hash (determinism). `make soak` runs the
# 10^7-step version tools/doc/pages/fuzzing-soak.md reports.
SB="$BUILD/harness/bin"
SW="$BUILD/check/soak"
mkdir -p "$SW"
for soak_v in se23-soak se23-soak-float; do
    for soak_a in on off; do
        check "soak-$soak_v-aided-$soak_a" "$SB/$soak_v" --steps 1000000 --aided "$soak_a"
    done
done
s_deterministic() {
    "$SB/$1" --steps 200000 --seed 7 >"$SW/$1-a.txt" 2>/dev/null &&
        "$SB/$1" --steps 200000 --seed 7 >"$SW/$1-b.txt" 2>/dev/null &&
        grep "final state hash" "$SW/$1-a.txt" &&
        cmp "$SW/$1-a.txt" "$SW/$1-b.txt"
}
# The table of these runs in tools/doc/pages/fuzzing-soak.md is current
# (tools/soak/table.sh from the four logs above; make doc-tables pastes it).
check soak-table-current sh -c 'sh tools/soak/table.sh format "$1/soak.md" \
    "$2"/soak-se23-soak-aided-on.log "$2"/soak-se23-soak-aided-off.log \
    "$2"/soak-se23-soak-float-aided-on.log "$2"/soak-se23-soak-float-aided-off.log &&
    /usr/bin/python3 tools/doc/tables.py --check --build "$3" soak-check' sh "$SW" "$LOGDIR" "$BUILD"
check soak-deterministic-double s_deterministic se23-soak
check soak-deterministic-float s_deterministic se23-soak-float
