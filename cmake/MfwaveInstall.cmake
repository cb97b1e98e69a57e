# What `cmake --install` adds beyond the targets (whose rules are in MfwaveTargets.cmake): the CMake
# package (find_package(mfwave 0.2)), the shipped scenes and reference tables, the plot scripts, and
# the Debian package CPack makes of it all. docs/install.md describes the installed tree.
include(CMakePackageConfigHelpers)

set(MFWAVE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/mfwave)
install(EXPORT mfwaveTargets NAMESPACE mfwave:: DESTINATION ${MFWAVE_CMAKE_DIR} FILE mfwaveTargets.cmake)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/mfwaveConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/mfwaveConfig.cmake INSTALL_DESTINATION ${MFWAVE_CMAKE_DIR})
# 0.x: a minor release may change the API, so 0.2 accepts 0.2.* only; from 1.0 on, SameMajorVersion.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mfwaveConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mfwaveConfig.cmake ${PROJECT_BINARY_DIR}/mfwaveConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindSuiteSparse.cmake
        DESTINATION ${MFWAVE_CMAKE_DIR})

# share/mfwave mirrors the source tree's data/ and analysis/ folders, so the drivers' lookup
# (io/run/ShippedData) and the plot scripts' relative paths work the same from either.
set(MFWAVE_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/mfwave)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/scenes ${PROJECT_SOURCE_DIR}/data/reference
        DESTINATION ${MFWAVE_SHARE_DIR}/data)
file(GLOB MFWAVE_PLOT_SCRIPTS ${PROJECT_SOURCE_DIR}/analysis/*.py)
install(FILES ${MFWAVE_PLOT_SCRIPTS} DESTINATION ${MFWAVE_SHARE_DIR}/analysis)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/analysis/tradeoff DESTINATION ${MFWAVE_SHARE_DIR}/analysis
        PATTERN __pycache__ EXCLUDE)

# The Debian package: everything above under /usr. Runtime dependencies come from dpkg-shlibdeps on
# the programs; the -dev packages a library user also needs are recommended, not required, so the
# programs install without a compiler.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME mfwave)
set(CPACK_PACKAGE_VENDOR "mfwave")
set(CPACK_PACKAGE_CONTACT "mfwave developers <mfwave@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "cmake, g++, pkg-config, libeigen3-dev, libsundials-dev, libsuitesparse-dev, libfftw3-dev, libvtk9-dev, libx11-dev, libopenmpi-dev, libcli11-dev, nlohmann-json3-dev, libtomlplusplus-dev, python3-matplotlib, python3-numpy")
include(CPack)
