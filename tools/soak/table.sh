#!/bin/sh
# The soak table of tools/doc/pages/fuzzing-soak.md (make doc-tables pastes
# it, tools/doc/tables.py), from the outputs of se23-soak (tools/soak/soak.c).
#
#   sh tools/soak/table.sh run BIN_DIR OUT.md ARG...
#       `make soak`: runs BIN_DIR/se23-soak and se23-soak-float, aided and
#       unaided, each with ARG... (--steps N --check-every K), prints their
#       outputs, keeps them beside OUT.md and writes the table into OUT.md;
#       exits 1 if a run failed.
#   sh tools/soak/table.sh format OUT.md LOG...
#       `make check` (tests/check.d/85-soak.sh): the table of outputs
#       already written (one per LOG, any order of the four runs).
set -u
mode=${1:?mode: run or format}
shift

format() { # OUT.md LOG...
    fo_out=$1
    shift
    awk '
    /se23-soak: (double|float), / {
        n++
        # se23-soak: double, aided (GNSS 1 Hz), 1000000 steps (5000 s at 200 Hz), seed 1
        # (after the progress lines of a log that holds stderr too)
        sub(/.*se23-soak: /, "se23-soak: ")
        split($0, h, ", ")
        prec[n] = h[1]; sub(/^se23-soak: /, "", prec[n])
        aid[n] = (h[2] ~ /^aided/) ? "aided" : "unaided"
        steps = h[3]; sub(/ steps.*/, "", steps)
        seed = $NF
    }
    /^  checks / { every = $4 }
    /worst \|R\^T R - I\|/ { rot[n] = $6 }
    /smallest eig\(P\)\/max/ { eig[n] = $3; sub(/^-/, "\342\210\222", eig[n]) }
    /non-finite states/ { nf[n] = $3 }
    /filter_errors/ { fe[n] = $2 }
    /final state hash/ { hash[n] = $4 }
    function commas(s, c) {
        c = ""
        while (length(s) > 3) { c = "," substr(s, length(s) - 2) c; s = substr(s, 1, length(s) - 3) }
        return s c
    }
    END {
        if (n == 0) exit 1
        printf "%s steps per run, seed %s, checked every %s steps and at the end:\n\n", commas(steps), seed, commas(every)
        print "| run | worst \\|RᵀR − I\\| | smallest eig(P) / largest | non-finite | failed steps | final-state hash |"
        print "|---|---:|---:|---:|---:|---|"
        for (p = 0; p < 2; p++) for (a = 0; a < 2; a++) for (i = 1; i <= n; i++) {
            if (prec[i] != (p ? "float" : "double") || aid[i] != (a ? "unaided" : "aided")) continue
            if (hash[i] == "") { print "table.sh: incomplete output " i > "/dev/stderr"; exit 1 }
            printf "| %s, %s | %s | %s | %s | %s | `%s` |\n", prec[i], aid[i], rot[i], eig[i], nf[i], fe[i], hash[i]
        }
    }' "$@" >"$fo_out.tmp" && mv "$fo_out.tmp" "$fo_out"
}

case "$mode" in
run)
    bin=${1:?BIN_DIR}
    out=${2:?OUT.md}
    shift 2
    mkdir -p "$(dirname "$out")"
    logs=""
    status=0
    for v in se23-soak se23-soak-float; do
        for a in on off; do
            log="${out%.md}-$v-aided-$a.txt"
            "$bin/$v" --aided "$a" "$@" >"$log" || status=1
            cat "$log"
            logs="$logs $log"
        done
    done
    # shellcheck disable=SC2086
    format "$out" $logs || exit 1
    echo
    cat "$out"
    echo "(written to $out; make doc-tables pastes it into tools/doc/pages/fuzzing-soak.md)"
    exit "$status"
    ;;
format)
    out=${1:?OUT.md}
    shift
    format "$out" "$@"
    ;;
*)
    echo "table.sh: unknown mode $mode (run or format)" >&2
    exit 2
    ;;
esac
