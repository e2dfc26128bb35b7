# The reference (make doc, tools/doc/doc.mk): Doxygen builds it from the
# public headers, the manual pages and the README (tools/doc/Doxyfile)
# with zero warnings, so that every public function, type, macro and
# struct field is documented, every parameter and return value of a
# function too, and every reference resolves. Doxygen's XML, built
# alongside, is audited for what Doxygen does not warn about: an
# undocumented enumerator or member of an anonymous union, and a header
# without @file (Doxygen leaves such a header's symbols out silently).
# Planted: a header with an undocumented function, struct field and macro
# must fail the build, each named; an undocumented enumerator and a header
# without @file must fail the audit.
DOC_OUT="$BUILD/check/doc"
case $DOC_OUT in /*) ;; *) DOC_OUT="$(pwd)/$DOC_OUT" ;; esac

# doc_config [LINE...]: tools/doc/Doxyfile with XML added and LINEs
# overriding its tags (a later assignment wins), for `doxygen -`. HTML
# stays on: Doxygen 1.9.4 run for XML alone warns that documented
# parameters are not.
doc_config() {
    cat tools/doc/Doxyfile
    echo "GENERATE_XML = YES"
    for line in "$@"; do
        echo "$line"
    done
}

# doc_warnings FILE: Doxygen's warnings in FILE, one line each (errors
# too: with WARN_AS_ERROR Doxygen calls its warnings errors), paths
# relative to the tree.
doc_warnings() {
    grep -E '(warning|error): ' "$1" | sed "s|^$(pwd)/||"
}

# doc_summary FILE: the first warnings, their count and the count per file
# (the end of the log, which a failed check prints).
doc_summary() {
    doc_warnings "$1" | head -n 20
    echo "doxygen: $(doc_warnings "$1" | wc -l) warnings (must be 0); per file:"
    doc_warnings "$1" | sed -nE 's/^([^ :]*):[0-9]+: .*/\1/p; s/^(warning|error): .*/(configuration)/p' |
        sort | uniq -c
}

# doc_audit XMLDIR: the files, structs and unions of include/se23/ and every
# member, enumerator included, that Doxygen's XML gives no description;
# fails if there is one.
doc_audit() {
    python3 - "$1" <<'EOF'
import glob, os, sys
import xml.etree.ElementTree as ET

def described(e):
    return any(''.join(d.itertext()).strip()
               for tag in ('briefdescription', 'detaileddescription', 'inbodydescription')
               for d in e.findall(tag))

bad = set()
for path in glob.glob(os.path.join(sys.argv[1], '*.xml')):
    for cd in ET.parse(path).getroot().iter('compounddef'):
        loc = cd.find('location')
        where = loc.get('file', '') if loc is not None else ''
        if '/include/se23/' not in '/' + where:
            continue
        name = cd.findtext('compoundname', '')
        if (cd.get('kind') in ('file', 'struct', 'union') and '@' not in name
                and not described(cd)):
            bad.add('%s: %s %s' % (where, cd.get('kind'), name))
        for m in cd.iter('memberdef'):
            ml = m.find('location')
            at = '%s:%s' % (ml.get('file'), ml.get('line')) if ml is not None else where
            if not described(m):
                bad.add('%s: %s %s::%s' % (at, m.get('kind'), name, m.findtext('name')))
            for ev in m.iter('enumvalue'):
                if not described(ev):
                    bad.add('%s: enumerator %s' % (at, ev.findtext('name')))
cwd = os.getcwd() + '/'
for b in sorted(bad):
    print('undocumented: ' + b.replace(cwd, ''))
print('doc audit: %d undocumented symbols in include/se23/' % len(bad))
sys.exit(1 if bad else 0)
EOF
}

doc_build() {
    rm -rf "$DOC_OUT/html" "$DOC_OUT/xml" && mkdir -p "$DOC_OUT" || return 1
    doc_config | SE23_DOC_OUT="$DOC_OUT" doxygen - 2>"$DOC_OUT/warnings.txt"
    rc=$?
    n=$(doc_warnings "$DOC_OUT/warnings.txt" | wc -l)
    doc_summary "$DOC_OUT/warnings.txt"
    echo "doxygen status $rc; reference: $DOC_OUT/html/index.html"
    [ "$rc" -eq 0 ] && [ "$n" -eq 0 ] && test -f "$DOC_OUT/html/index.html"
}
check doc-builds-without-warnings doc_build

check doc-documents-every-symbol doc_audit "$DOC_OUT/xml"

doc_fails_on_planted_symbols() {
    p="$DOC_OUT/planted"
    rm -rf "$p" && mkdir -p "$p/include/se23" && cp include/se23/*.h "$p/include/se23/" &&
        cat >"$p/include/se23/planted.h" <<'EOF' &&
/** @file planted.h
 *  @brief A header with undocumented symbols (check step 52-doc). */
#ifndef SE23_PLANTED_H
#define SE23_PLANTED_H
#define SE23_PLANTED_MACRO 1
/** A documented struct with an undocumented field. */
typedef struct {
    int planted_field;
} se23_planted_t;
/** A documented enum with an undocumented enumerator. */
enum { SE23_PLANTED_ENUM = 0 };
int se23_planted(int x);
#endif
EOF
        printf '/* a header without @file */\nint se23_planted_nofile(int x);\n' \
            >"$p/include/se23/planted_nofile.h" || return 1
    doc_config "INPUT = $p/include/se23" "USE_MDFILE_AS_MAINPAGE =" |
        SE23_DOC_OUT="$p/out" doxygen - 2>"$p/warnings.txt"
    rc=$?
    doc_warnings "$p/warnings.txt"
    echo "doxygen status $rc (must fail)"
    [ "$rc" -ne 0 ] || return 1
    for sym in "se23_planted(int" planted_field SE23_PLANTED_MACRO; do
        doc_warnings "$p/warnings.txt" | grep -q "planted.h:.*$sym" ||
            { echo "no warning names $sym"; return 1; }
    done
    if doc_audit "$p/out/xml" >"$p/audit.txt"; then
        cat "$p/audit.txt"
        echo "the audit passed a tree with planted symbols"
        return 1
    fi
    cat "$p/audit.txt"
    for sym in SE23_PLANTED_ENUM se23_planted_nofile; do
        grep -q "$sym" "$p/audit.txt" || { echo "the audit does not name $sym"; return 1; }
    done
}
check doc-fails-on-planted-symbols doc_fails_on_planted_symbols
# The README's five-minute example (tools/doc/example.c, quoted there)
# compiles in both precisions with the strict flags.
for doc_d in 0 1; do
    check "doc-example-compiles-double$doc_d" cc -std=c99 -Wall -Wextra -Wpedantic -Werror \
        -Iinclude -Iport -DSE23_CFG_DOUBLE=$doc_d -c tools/doc/example.c \
        -o "$BUILD/check/doc-example-$doc_d.o"
done
# ... and the README quotes it as it is (from its first #include on).
doc_example_quoted() {
    /usr/bin/python3 - "$@" <<'PY'
import sys
src = open("tools/doc/example.c", encoding="utf-8").read()
body = src[src.index("#include"):]
readme = open("README.md", encoding="utf-8").read()
sys.exit(0 if "```c\n" + body + "```" in readme else 1)
PY
}
check doc-example-quoted-current doc_example_quoted
