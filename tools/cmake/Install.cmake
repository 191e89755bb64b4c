# `cmake --install build --prefix DIR` (docs/install.md): the program, the run-time data it finds
# beside itself in share/tstyles, the man page written from its own help, the desktop entry, MIME
# types and icons, and the Python package. Nothing installed refers back to the source or build tree.
include(GNUInstallDirs)
# `make install` and `cpack` install what is built, without building `all` first: `all` holds the
# tests, most of the build's time, and none of them is installed. Build, then install or pack. A
# build without the tests (TSTYLES_TESTS=OFF, the Python package's) builds `all` when installing.
if(TSTYLES_TESTS)
  set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
endif()

install(TARGETS tstyles RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The bundled data, found from the executable as ../share/tstyles (src/core/bundled_data.cpp). The
# datasets are generated at build time into the source tree's data/; the small ones are installed
# with the scenes that use them (sizes in docs/install.md): the partly overlapping super-ellipsoid
# (Figures 1 and 4, the scene `view` opens by default), the hurricane (Figure 5, Figure 6 left, the
# compositor examples) and the warped box. The sonar survey (19 MiB) and the aligned
# super-ellipsoid (11 MiB) are test and benchmark data: they and their scenes stay out.
set(TSTYLES_INSTALL_DATA_DIR ${CMAKE_INSTALL_DATADIR}/tstyles)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/data/styles ${CMAKE_SOURCE_DIR}/data/superellipsoid
                  ${CMAKE_SOURCE_DIR}/data/hurricane ${CMAKE_SOURCE_DIR}/data/warped-box
        DESTINATION ${TSTYLES_INSTALL_DATA_DIR})
file(GLOB TSTYLES_INSTALLED_SCENES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/data/scenes/figure1-*.json
     ${CMAKE_SOURCE_DIR}/data/scenes/figure4-*.json ${CMAKE_SOURCE_DIR}/data/scenes/figure5-*.json
     ${CMAKE_SOURCE_DIR}/data/scenes/figure6-left-*.json ${CMAKE_SOURCE_DIR}/data/scenes/compositors-hurricane-*.json
     ${CMAKE_SOURCE_DIR}/data/scenes/warped-box-*.json)
install(FILES ${TSTYLES_INSTALLED_SCENES} DESTINATION ${TSTYLES_INSTALL_DATA_DIR}/scenes)

set(TSTYLES_PACKAGING_DIR ${CMAKE_BINARY_DIR}/packaging)
# Who answers for the package: the .deb's Maintainer, the changelog's signature and the copyright's
# contact. A packager who builds their own sets theirs.
set(TSTYLES_MAINTAINER "Temporal Styles developers <developers@temporal-styles.org>"
    CACHE STRING "The package maintainer, as \"Name <address>\"")

# tstyles.1 from the program's own options (the hidden `tstyles manual-page`), so it never
# disagrees with --help; tests/cli/install_test.sh compares the two.
set(TSTYLES_MAN_PAGE ${CMAKE_BINARY_DIR}/man/tstyles.1)
add_custom_command(OUTPUT ${TSTYLES_MAN_PAGE}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
  COMMAND tstyles manual-page --output ${TSTYLES_MAN_PAGE}
  DEPENDS tstyles
  COMMENT "Writing the man page tstyles.1 from tstyles --help"
  VERBATIM)
# Installed compressed, as Debian's policy asks (gzip -9n: no name or time stamp, so the same page
# gives the same bytes).
set(TSTYLES_MAN_PAGE_GZ ${TSTYLES_MAN_PAGE}.gz)
add_custom_command(OUTPUT ${TSTYLES_MAN_PAGE_GZ}
  COMMAND gzip -9 -n -f -k ${TSTYLES_MAN_PAGE}
  DEPENDS ${TSTYLES_MAN_PAGE}
  COMMENT "Compressing the man page"
  VERBATIM)
add_custom_target(tstyles_manual_page ALL DEPENDS ${TSTYLES_MAN_PAGE} ${TSTYLES_MAN_PAGE_GZ})
install(FILES ${TSTYLES_MAN_PAGE_GZ} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# The package's documents where Debian looks for them: the copyright in the machine-readable
# format (the licence is the MIT, "Expat" in Debian's words) and the changelog of this version,
# compressed (tools/packaging/; the changelog's entry takes the project's version).
set(TSTYLES_DOC_DIR ${CMAKE_INSTALL_DATADIR}/doc/tstyles)
configure_file(${CMAKE_SOURCE_DIR}/tools/packaging/changelog.in ${TSTYLES_PACKAGING_DIR}/changelog @ONLY)
configure_file(${CMAKE_SOURCE_DIR}/tools/packaging/copyright.in ${TSTYLES_PACKAGING_DIR}/copyright @ONLY)
add_custom_command(OUTPUT ${TSTYLES_PACKAGING_DIR}/changelog.gz
  COMMAND gzip -9 -n -f -k ${TSTYLES_PACKAGING_DIR}/changelog
  DEPENDS ${TSTYLES_PACKAGING_DIR}/changelog
  COMMENT "Compressing the package's changelog"
  VERBATIM)
add_custom_target(tstyles_changelog ALL DEPENDS ${TSTYLES_PACKAGING_DIR}/changelog.gz)
install(FILES ${TSTYLES_PACKAGING_DIR}/changelog.gz ${TSTYLES_PACKAGING_DIR}/copyright
        DESTINATION ${TSTYLES_DOC_DIR})

# The desktop: the applications menu entry and the MIME types for the files no shared-mime-info
# type covers, written from the format table by the hidden `tstyles packaging-file` (so that every
# format the program reads is offered for its files; tstyles/data/format_listing.h), with the
# package's description (tools/cmake/Packaging.cmake); and the icon (tools/packaging/icons, drawn by
# tools/packaging/make_icons.sh from a rendered scene).
set(TSTYLES_DESKTOP_ENTRY ${TSTYLES_PACKAGING_DIR}/tstyles.desktop)
set(TSTYLES_MIME_PACKAGE ${TSTYLES_PACKAGING_DIR}/tstyles.xml)
set(TSTYLES_PACKAGE_DESCRIPTION ${TSTYLES_PACKAGING_DIR}/description.txt)
add_custom_command(OUTPUT ${TSTYLES_DESKTOP_ENTRY} ${TSTYLES_MIME_PACKAGE} ${TSTYLES_PACKAGE_DESCRIPTION}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${TSTYLES_PACKAGING_DIR}
  COMMAND tstyles packaging-file desktop-entry --output ${TSTYLES_DESKTOP_ENTRY}
  COMMAND tstyles packaging-file mime-package --output ${TSTYLES_MIME_PACKAGE}
  COMMAND tstyles packaging-file description --output ${TSTYLES_PACKAGE_DESCRIPTION}
  DEPENDS tstyles
  COMMENT "Writing the desktop entry, the MIME package and the package description from the format table"
  VERBATIM)
add_custom_target(tstyles_packaging_files ALL
                  DEPENDS ${TSTYLES_DESKTOP_ENTRY} ${TSTYLES_MIME_PACKAGE} ${TSTYLES_PACKAGE_DESCRIPTION})
install(FILES ${TSTYLES_DESKTOP_ENTRY} DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${TSTYLES_MIME_PACKAGE} DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages)
foreach(size 48 128 256)
  install(FILES ${CMAKE_SOURCE_DIR}/tools/packaging/icons/tstyles-${size}.png
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps RENAME tstyles.png)
endforeach()
