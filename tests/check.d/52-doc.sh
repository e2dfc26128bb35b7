# The reference (make doc, tools/doc/doc.mk): Doxygen builds it from the
# public headers and the README, and its warnings (undocumented parameters
# and members) are at most DOC_WARNINGS_MAX: a new public symbol comes
# documented. A header with an undocumented function planted must raise
# the count, so the count can fail.
DOC_OUT="$BUILD/check/doc"
case $DOC_OUT in /*) ;; *) DOC_OUT="$(pwd)/$DOC_OUT" ;; esac
doc_build() {
    mkdir -p "$DOC_OUT" &&
        SE23_DOC_OUT="$DOC_OUT" doxygen tools/doc/Doxyfile 2>"$DOC_OUT/warnings.txt" &&
        test -f "$DOC_OUT/html/index.html" &&
        max=$(sed -n 's/^DOC_WARNINGS_MAX := //p' tools/doc/doc.mk) &&
        n=$(grep -c 'warning:' "$DOC_OUT/warnings.txt") &&
        echo "doxygen: $n warnings (at most $max)" && [ "$n" -le "$max" ]
}
check doc-builds-within-its-warnings doc_build
doc_counts_a_planted_symbol() {
    rm -rf "$DOC_OUT/planted" && mkdir -p "$DOC_OUT/planted/include" &&
        cp -r include/se23 "$DOC_OUT/planted/include/" &&
        printf '/** @file planted.h\n @brief a header with one undocumented function */\n#ifndef PLANTED_H\n#define PLANTED_H\nint se23_planted(int x);\n#endif\n' \
            >"$DOC_OUT/planted/include/se23/planted.h" &&
        sed 's|^INPUT .*|INPUT = planted/include/se23|; s|^USE_MDFILE_AS_MAINPAGE.*||' \
            tools/doc/Doxyfile >"$DOC_OUT/planted/Doxyfile" &&
        (cd "$DOC_OUT" && SE23_DOC_OUT="$DOC_OUT/planted/out" doxygen planted/Doxyfile \
            2>planted/warnings.txt) &&
        grep -q "se23_planted" "$DOC_OUT/planted/warnings.txt"
}
check doc-counts-a-planted-symbol doc_counts_a_planted_symbol
