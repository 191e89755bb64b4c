# The .deb: `cpack -G DEB` in the build folder packs what `cmake --install` installs, under /usr
# (docs/install.md). Its dependencies come from the shared libraries the program and the Python
# module link (dpkg-shlibdeps), plus what is loaded by name at run time.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME tstyles)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Temporal Styles")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Time-varying volume rendering with temporal style transfer functions")
# The long description names every format the program reads: the build writes it from the format
# table (tools/cmake/Install.cmake), and cpack reads it when it packs (CPACK_PROJECT_CONFIG_FILE).
configure_file(${CMAKE_SOURCE_DIR}/tools/packaging/cpack_description.cmake.in
               ${CMAKE_BINARY_DIR}/packaging/cpack_description.cmake @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_BINARY_DIR}/packaging/cpack_description.cmake)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${TSTYLES_MAINTAINER}")  # tools/cmake/Install.cmake
# Debian installs binaries stripped as dh_strip strips them (the build folder keeps the symbols):
# run on the staged files before they are packed.
set(CPACK_PRE_BUILD_SCRIPTS ${CMAKE_SOURCE_DIR}/tools/packaging/strip_binaries.cmake)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Loaded by name, so dpkg-shlibdeps cannot see them: the legend font (src/annotate/font.cpp) and
# Mesa's drivers behind EGL (llvmpipe where there is no GPU).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core, libgl1-mesa-dri")
# The Python module is built for this build's Python (its ABI, e.g. cpython-311) and imports numpy
# (xarray for from_xarray); the program itself needs neither, so they are recommended only.
if(TARGET tstyles_python)
  math(EXPR TSTYLES_NEXT_PYTHON_MINOR "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), \
python3 (<< ${Python_VERSION_MAJOR}.${TSTYLES_NEXT_PYTHON_MINOR}), python3-numpy")
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-xarray")
endif()
include(CPack)
