#!/usr/bin/env bash
# `cmake --install` end to end (docs/install.md): the installed program, moved to another prefix,
# works with the source and build trees hidden; the installed Python package renders; the man page
# lists what --help lists; the desktop entry and the MIME types are valid.
# Called by ctest with BUILD_DIR, CMAKE_COMMAND and PYTHON in the environment.
# shellcheck source=cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh"

: "${BUILD_DIR:?the build folder to install from}"
: "${CMAKE_COMMAND:=cmake}"
: "${PYTHON:=python3}"

# Installs the build into SCRATCH/prefix, then moves it to a folder outside the source and build
# trees (they are hidden below, the scratch folder with them): sets PREFIX to the moved copy.
install_and_move() {
    "$CMAKE_COMMAND" --install "$BUILD_DIR" --prefix "$SCRATCH/prefix" >"$SCRATCH/install.log" 2>&1 ||
        fail "cmake --install failed: $(tail -5 "$SCRATCH/install.log")"
    PREFIX=$(mktemp -d /tmp/tstyles-installed.XXXXXX)
    trap 'rm -rf "$PREFIX"' EXIT
    cp -a "$SCRATCH/prefix/." "$PREFIX/"
    rm -rf "$SCRATCH/prefix"
    cd "$PREFIX" || fail "cannot enter $PREFIX"
}

# Runs a command with the source and build trees out of sight: in a private mount namespace, an
# empty tmpfs over each, so that nothing compiled in can reach them. Where namespaces are not
# allowed it runs in plain sight and says so (the data folder's check below still holds).
run_hidden() {
    local mounts="mount -t tmpfs none '$SOURCE_DIR'"
    case "$BUILD_DIR/" in "$SOURCE_DIR"/*) ;; *) mounts="$mounts && mount -t tmpfs none '$BUILD_DIR'" ;; esac
    if unshare --mount true 2>/dev/null; then
        unshare --mount sh -c "$mounts && exec \"\$@\"" hidden "$@"
    elif unshare --mount --map-root-user true 2>/dev/null; then
        unshare --mount --map-root-user sh -c "$mounts && exec \"\$@\"" hidden "$@"
    else
        echo "note: no mount namespace here; the source and build trees stay visible" >&2
        "$@"
    fi
}

# The installed program, run hidden from the trees, with TSTYLES_DATA_DIR unset: run_installed ARGS...
run_installed() {
    echo "+ (installed, trees hidden) tstyles $*" >&2
    RC=0
    run_hidden env -u TSTYLES_DATA_DIR "$PREFIX/bin/tstyles" "$@" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
}

case_relocated_prefix_renders() {
    install_and_move
    run_installed --version
    expect_exit 0
    expect_stdout_contains "tstyles "
    expect_stdout_contains "OpenGL: "
    expect_stdout_contains "Data: $PREFIX/share/tstyles (installed beside the program)"
    # A user's dataset in a folder of their own: the installed super-ellipsoid, copied.
    mkdir -p "$PREFIX/home/bounce"
    cp "$PREFIX/share/tstyles/superellipsoid/"* "$PREFIX/home/bounce/"
    run_installed render "$PREFIX/home/bounce/series.json" -o "$PREFIX/home/bounce.png" --width 64 --height 48
    expect_exit 0
    expect_image "$PREFIX/home/bounce.png" 64 48
    # The bundled scene with lit-sphere styles: the built-in styles are read from share/tstyles.
    run_installed render "$PREFIX/share/tstyles/scenes/figure1-styled-focus-step3.json" -o "$PREFIX/home/figure1.png" \
        --width 64 --height 64
    expect_exit 0
    expect_image "$PREFIX/home/figure1.png" 64 64
}

case_relocated_prefix_animates_with_legend() {
    install_and_move
    run_installed animate "$PREFIX/share/tstyles/scenes/figure1-focus-step3.json" -o "$PREFIX/frames/" \
        --width 96 --height 64 --sweep-focus 1 --frames 3 --legend
    expect_exit 0
    [ "$(find "$PREFIX/frames" -name 'frame-*.png' | wc -l)" -eq 3 ] || fail "expected 3 frames"
    expect_image "$PREFIX/frames/frame-0000.png" 96 64
}

case_python_package_renders_numpy() {
    install_and_move
    local site="$PREFIX/lib/python3/dist-packages"
    [ -d "$site/tstyles" ] || fail "the Python package is not in $site"
    echo "+ (installed, trees hidden) python3 renders a numpy series" >&2
    RC=0
    run_hidden env -u TSTYLES_DATA_DIR PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$PYTHON" -c '
import sys, numpy as np, tstyles
assert tstyles.__file__.startswith(sys.argv[1]), tstyles.__file__
z, y, x = np.meshgrid(np.linspace(-1, 1, 16), np.linspace(-1, 1, 16), np.linspace(-1, 1, 16), indexing="ij")
steps = [np.exp(-4 * ((x - 0.3 * t) ** 2 + y ** 2 + z ** 2)).astype(np.float32) for t in range(3)]
series = tstyles.Series(np.stack(steps))
image = tstyles.render(series, tstyles.Scene.automatic(series), 40, 30)
assert image.shape == (30, 40, 4), image.shape
assert np.asarray(image)[..., :3].std() > 0, "one colour all over"
print("styles:", len(tstyles.built_in_styles()))
' "$site" >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
    expect_exit 0
    grep -qE "^styles: [1-9]" "$OUT_FILE" || fail "the installed module found no built-in styles"
}

# `pip install ./python` (python/setup.py, scikit-build): the package is named tstyles and carries
# the program's version, read from the project's CMakeLists.txt. (The pip build itself, 9.5 minutes,
# is not run here: docs/install.md.)
case_python_package_metadata() {
    RC=0
    (cd "$SOURCE_DIR/python" && "$PYTHON" setup.py --name --version) >"$OUT_FILE" 2>"$ERR_FILE" || RC=$?
    expect_exit 0
    local version
    version=$("$TSTYLES" --version | sed -n 's/^tstyles //p')
    [ -n "$version" ] || fail "tstyles --version printed no version"
    [ "$(tail -2 "$OUT_FILE" | tr '\n' ' ')" = "tstyles $version " ] ||
        fail "setup.py says '$(tail -2 "$OUT_FILE" | tr '\n' ' ')', the program 'tstyles $version'"
}

# Option names on a help text's option lines ("  -o,--output TEXT ..."): the first column only
# (descriptions mention other options), one name a line, sorted.
help_options() {
    grep -E '^  +-' | awk '{print $1}' | tr ',' '\n' | sort -u
}

# The subcommands --help lists, one a line.
help_subcommands() {
    sed -n '/^Subcommands:/,/^$/p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p' | sort -u
}

case_manual_page_matches_help() {
    local page="$BUILD_DIR/man/tstyles.1"
    [ -f "$page" ] || fail "$page was not built"
    # The page as text, hyphens unescaped, cut into one file per section (SUBCOMMAND or "main").
    local text="$SCRATCH/page.txt"
    sed 's/\\-/-/g; s/\\f[BIR]//g' "$page" >"$text"
    run_tstyles -- --help
    expect_exit 0
    local subcommands
    subcommands=$(help_subcommands <"$OUT_FILE")
    [ -n "$subcommands" ] || fail "no subcommands found in tstyles --help"
    help_options <"$OUT_FILE" >"$SCRATCH/main.help"
    sed -n '/^\.SH OPTIONS/,/^\.SH SUBCOMMANDS/p' "$text" | grep -E '^-' | help_options_of_page >"$SCRATCH/main.page"
    diff "$SCRATCH/main.help" "$SCRATCH/main.page" >&2 || fail "tstyles --help and the page's OPTIONS differ"
    local listed
    listed=$(sed -n 's/^\.SS "tstyles \(.*\)"$/\1/p' "$text" | sort -u)
    [ "$listed" = "$subcommands" ] || fail "subcommands: --help lists [$subcommands], the page [$listed]"
    local sub
    for sub in $subcommands; do
        run_tstyles -- "$sub" --help
        expect_exit 0
        help_options <"$OUT_FILE" >"$SCRATCH/$sub.help"
        awk -v head=".SS \"tstyles $sub\"" '$0 == head {on = 1; next} /^\.S[SH] / {on = 0} on' "$text" |
            grep -E '^-' | help_options_of_page >"$SCRATCH/$sub.page"
        diff "$SCRATCH/$sub.help" "$SCRATCH/$sub.page" >&2 || fail "tstyles $sub --help and the page differ"
    done
}

# Option names on the page's tagged lines ("-o, --output TEXT"), one a line, sorted.
help_options_of_page() {
    sed 's/, /,/g' | awk '{print $1}' | tr ',' '\n' | sort -u
}

case_desktop_entry_and_mime_types_valid() {
    # Written by the build from the format table (tools/cmake/Install.cmake).
    local entry="$BUILD_DIR/packaging/tstyles.desktop"
    if command -v desktop-file-validate >/dev/null; then
        desktop-file-validate "$entry" >&2 || fail "desktop-file-validate rejects $entry"
    else
        echo "note: desktop-file-validate missing (desktop-file-utils); checking the keys only" >&2
    fi
    grep -qx 'Exec=tstyles view %F' "$entry" || fail "Exec is not 'tstyles view %F'"
    grep -qx 'Categories=Science;DataVisualization;' "$entry" || fail "Categories are not Science;DataVisualization;"
    # The MIME package: well-formed, and accepted by update-mime-database, which then knows our types.
    local mime="$SCRATCH/mime"
    mkdir -p "$mime/packages"
    cp "$BUILD_DIR/packaging/tstyles.xml" "$mime/packages/tstyles.xml"
    xmllint --noout "$mime/packages/tstyles.xml" || fail "the MIME package is not well-formed XML"
    # Our temporary share/ on the search path, or update-mime-database warns that nothing will look there.
    XDG_DATA_DIRS="$SCRATCH" XDG_DATA_HOME="$SCRATCH" update-mime-database "$mime" 2>"$SCRATCH/mime.log" ||
        fail "update-mime-database: $(cat "$SCRATCH/mime.log")"
    [ ! -s "$SCRATCH/mime.log" ] || fail "update-mime-database warns: $(cat "$SCRATCH/mime.log")"
    local type
    for type in x-nifti x-nrrd x-vtk-xml x-tstyles-series x-tstyles-scene; do
        [ -f "$mime/application/$type.xml" ] || fail "update-mime-database did not register application/$type"
    done
    # Every type the entry opens is ours or the system's.
    local listed
    for listed in $(sed -n 's/^MimeType=//p' "$entry" | tr ';' ' '); do
        [ -f "$mime/$listed.xml" ] || [ -f "/usr/share/mime/$listed.xml" ] ||
            fail "the desktop entry opens $listed, which no MIME package defines"
    done
    # The desktop offers the program for a TIFF, a DICOM file and a VTK image: their types are listed.
    local offered
    for offered in image/tiff application/dicom application/x-vtk-xml; do
        grep -q "^MimeType=.*$offered;" "$entry" || fail "the desktop entry does not open $offered"
    done
    # The icon in its three sizes, each square at its size.
    local size
    for size in 48 128 256; do
        expect_image "$SOURCE_DIR/tools/packaging/icons/tstyles-$size.png" "$size" "$size"
    done
}

# The .deb (`cpack -G DEB`, tools/cmake/Packaging.cmake), written into the scratch folder: what is
# in it, and the dependencies dpkg-shlibdeps found beside the ones named by hand.
case_deb_package_contents() {
    command -v dpkg-shlibdeps >/dev/null || fail "dpkg-shlibdeps missing (dpkg-dev): the .deb cannot be built"
    "${CPACK_COMMAND:-cpack}" --config "$BUILD_DIR/CPackConfig.cmake" -G DEB -B "$SCRATCH/deb" \
        >"$SCRATCH/cpack.log" 2>&1 || fail "cpack failed: $(tail -5 "$SCRATCH/cpack.log")"
    local deb
    deb=$(find "$SCRATCH/deb" -maxdepth 1 -name 'tstyles_*_*.deb')
    [ -f "$deb" ] || fail "no tstyles_*.deb in $SCRATCH/deb"
    dpkg-deb -c "$deb" | awk '{print $6}' >"$SCRATCH/contents.txt"
    local path
    for path in ./usr/bin/tstyles ./usr/share/man/man1/tstyles.1.gz ./usr/share/applications/tstyles.desktop \
        ./usr/share/doc/tstyles/copyright ./usr/share/doc/tstyles/changelog.gz \
        ./usr/share/mime/packages/tstyles.xml ./usr/share/icons/hicolor/48x48/apps/tstyles.png \
        ./usr/share/tstyles/styles/styles.json ./usr/share/tstyles/scenes/figure1-styled-focus-step3.json \
        ./usr/share/tstyles/superellipsoid/series.json ./usr/lib/python3/dist-packages/tstyles/__init__.py; do
        grep -qxF "$path" "$SCRATCH/contents.txt" || fail "the .deb lacks $path"
    done
    grep -q '^./usr/lib/python3/dist-packages/tstyles/_native\..*\.so$' "$SCRATCH/contents.txt" ||
        fail "the .deb lacks the Python extension module"
    if grep -qE 'build|/work/|/home/' "$SCRATCH/contents.txt"; then fail "the .deb holds paths of the build machine"; fi
    # Its description names the formats from the table, the latest rows too.
    local description
    description=$(dpkg-deb -f "$deb" Description)
    local format
    for format in NetCDF NIfTI VTK DICOM OME-Zarr TIFF Plot3D; do
        case "$description" in *"$format"*) ;; *) fail "the description lacks $format: $description" ;; esac
    done
    local depends
    depends=$(dpkg-deb -f "$deb" Depends)
    case "$depends" in *fonts-dejavu-core*libegl1*) ;; *) fail "Depends lacks the font or libegl1: $depends" ;; esac
}

# Debian's own checker finds nothing to say of the .deb: binaries stripped, the man page
# compressed, a machine-readable copyright, a changelog, a maintainer address of the proper form.
# Every tag lintian prints (error, warning, info, pedantic) fails the case.
case_deb_passes_lintian() {
    command -v lintian >/dev/null || fail "lintian missing (tools/install_dependencies.sh installs it)"
    "${CPACK_COMMAND:-cpack}" --config "$BUILD_DIR/CPackConfig.cmake" -G DEB -B "$SCRATCH/deb" \
        >"$SCRATCH/cpack.log" 2>&1 || fail "cpack failed: $(tail -5 "$SCRATCH/cpack.log")"
    local deb
    deb=$(find "$SCRATCH/deb" -maxdepth 1 -name 'tstyles_*_*.deb')
    [ -f "$deb" ] || fail "no tstyles_*.deb in $SCRATCH/deb"
    lintian --display-level ">=pedantic" --tag-display-limit 0 "$deb" >"$SCRATCH/lintian.txt" 2>&1
    # lintian warns that it runs as root (CI does); that is about the run, not the package.
    if grep -E '^[EWIPX]: ' "$SCRATCH/lintian.txt" >"$SCRATCH/tags.txt"; then
        fail "lintian found $(wc -l <"$SCRATCH/tags.txt") tag(s): $(head -5 "$SCRATCH/tags.txt")"
    fi
    # And the package is what lintian read: its maintainer has a name and an address.
    dpkg-deb -f "$deb" Maintainer | grep -qE '^[^<>]+ <[^@<> ]+@[^@<> ]+\.[a-z]+>$' ||
        fail "the Maintainer field is not 'Name <address>': $(dpkg-deb -f "$deb" Maintainer)"
}

"case_$CASE"
