# Gates on the library objects built for Cortex-M (make cross; the images of
# 40-target.sh, tv_test and ins_replay, supply newlib's code for the stack
# analysis):
#  - no soft-double call in the float (M4F) build, no heap and no stdio in
#    either build (tools/target/symbol_gate.py, on objects, not images);
#  - worst-case stack of every public function, callees included, within
#    tests/target/budgets/stack.txt (tools/target/stack_gate.py, from the
#    -fstack-usage/-fcallgraph-info=su output);
#  - .text + .rodata of the library within tests/target/budgets/size.txt;
#  - and, a report rather than a gate, what a firmware links of it
#    (tools/target/footprint.py on the footprint images' link maps; fails
#    only if a map cannot be read).
# Each gate is also shown to reject a fixture built to violate it
# (tests/target/gate_fixtures), so a gate that cannot fail would show here.
PY3=/usr/bin/python3
GATE_LIB_M4F="$BUILD/lib-m4f-float"
GATE_LIB_M7="$BUILD/lib-m7-double"
GATE_FIX="$BUILD/target/gate-fixtures"

# gate_rejects NAME PATTERN CMD...: CMD must fail and print PATTERN.
gate_rejects() {
    gr_pattern=$2
    gr_name=$1
    shift 2
    check "$gr_name" sh -c '"$@" >"$0.out" 2>&1; rc=$?; cat "$0.out";
        [ "$rc" -ne 0 ] && grep -q -- "$1" "$0.out"' \
        "$LOGDIR/$gr_name" "$gr_pattern" "$@"
}

check gate-build-fixtures make -s gate-fixtures BUILD="$BUILD"
check gate-m4f-no-soft-double $PY3 tools/target/symbol_gate.py soft-double "$GATE_LIB_M4F"/*.o
gate_rejects gate-soft-double-rejects-fixture "__aeabi_dmul used by fixture_double" \
    $PY3 tools/target/symbol_gate.py soft-double "$GATE_FIX/bad_symbols/bad_symbols.o"
for gate_v in m4f-float m7-double; do
    check "gate-$gate_v-no-heap" $PY3 tools/target/symbol_gate.py heap "$BUILD/lib-$gate_v"/*.o
    check "gate-$gate_v-no-stdio" $PY3 tools/target/symbol_gate.py stdio "$BUILD/lib-$gate_v"/*.o
    check "gate-$gate_v-stack" $PY3 tools/target/stack_gate.py "$BUILD/lib-$gate_v" \
        "$BUILD/target/$gate_v/tv_test.elf,$BUILD/target/$gate_v/ins_replay.elf" \
        tests/target/budgets/stack.txt "$gate_v"
    check "gate-$gate_v-size" $PY3 tools/target/size_gate.py "$BUILD/lib-$gate_v/libse23.a" \
        tests/target/budgets/size.txt "$gate_v"
done
check footprint-images make -s footprint-images BUILD="$BUILD"
for gate_v in m4f-float m7-double; do
    check "footprint-$gate_v" $PY3 tools/target/footprint.py "$gate_v" \
        "$BUILD/target/$gate_v/footprint_kernels.map" "$BUILD/target/$gate_v/footprint_filter.map" \
        "$BUILD/target/$gate_v/footprint_none.map"
done
gate_rejects gate-heap-rejects-fixture "malloc used by fixture_heap" \
    $PY3 tools/target/symbol_gate.py heap "$GATE_FIX/bad_symbols/bad_symbols.o"
gate_rejects gate-stdio-rejects-fixture "printf used by fixture_stdio" \
    $PY3 tools/target/symbol_gate.py stdio "$GATE_FIX/bad_symbols/bad_symbols.o"
gate_rejects gate-stack-rejects-vla "dynamic stack" \
    $PY3 tools/target/stack_gate.py "$GATE_FIX/bad_vla" "$BUILD/target/m4f-float/tv_test.elf" \
    tests/target/budgets/stack.txt m4f-float --roots fixture_vla
gate_rejects gate-stack-rejects-recursion "recursion: fixture_recursion" \
    $PY3 tools/target/stack_gate.py "$GATE_FIX/bad_recursion" "$BUILD/target/m4f-float/tv_test.elf" \
    tests/target/budgets/stack.txt m4f-float --roots fixture_recursion
# The Cortex-M port's math override header builds the library warning-free.
check gate-port-opts make -s port-opts BUILD="$BUILD"
# The footprint table of tools/doc/pages/cortex-m.md is the one these link
# maps give (tools/target/report.py; make doc-tables pastes it).
check target-footprint-table-current sh -c '/usr/bin/python3 tools/target/report.py "$1" \
    --only footprint && /usr/bin/python3 tools/doc/tables.py --check --build "$1" \
    target-footprint' sh "$BUILD"
