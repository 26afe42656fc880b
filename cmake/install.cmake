# `cmake --install`: the tool, its presets and schema, and the cascade math as a CMake package
# (find_package(shadowtune) -> shadowtune::csm). Tests and fuzzers install nothing.
include(CMakePackageConfigHelpers)
set(ST_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shadowtune)
set(ST_DATA_DIR ${CMAKE_INSTALL_DATADIR}/shadowtune)

install(TARGETS shadowtune RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The editor falls back to <prefix>/share/shadowtune/presets (app/preset_dir.h). The scene
# presets name glTF files by relative path (../../../shared/assets/...): installed too, they
# need those assets at <prefix>/share/shared/assets or a path edited to where the assets are.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/presets/ DESTINATION ${ST_DATA_DIR}/presets FILES_MATCHING PATTERN "*.json")
install(FILES ${CMAKE_SOURCE_DIR}/schema/preset.schema.json ${CMAKE_SOURCE_DIR}/schema/sweep.schema.json
  DESTINATION ${ST_DATA_DIR}/schema)

# The headers shadowtune::csm needs, at their paths in the source tree.
set(ST_HEADER_DIR ${CMAKE_INSTALL_INCLUDEDIR}/shadowtune)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/renderer/csm/ DESTINATION ${ST_HEADER_DIR}/renderer/csm FILES_MATCHING PATTERN "*.h")
install(FILES ${CMAKE_SOURCE_DIR}/renderer/settings/settings.h ${CMAKE_SOURCE_DIR}/renderer/settings/split_range.h DESTINATION ${ST_HEADER_DIR}/renderer/settings)
# settings.h includes shaders/codes.h (plain #defines, valid C++ and GLSL) once that exists.
install(FILES ${CMAKE_SOURCE_DIR}/shaders/codes.h DESTINATION ${ST_HEADER_DIR}/shaders OPTIONAL)

# Their include directory, <prefix>/include/shadowtune, comes from the targets' INSTALL_INTERFACE.
install(TARGETS st_csm st_settings_types EXPORT shadowtuneTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT shadowtuneTargets NAMESPACE shadowtune:: DESTINATION ${ST_CMAKE_DIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/shadowtuneConfig.cmake.in
  ${CMAKE_BINARY_DIR}/shadowtuneConfig.cmake INSTALL_DESTINATION ${ST_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/shadowtuneConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/shadowtuneConfig.cmake ${CMAKE_BINARY_DIR}/shadowtuneConfigVersion.cmake
  DESTINATION ${ST_CMAKE_DIR})

# `cpack -G DEB` in the build folder. The binary's libraries become Depends through
# dpkg-shlibdeps (dpkg-dev, and file to find the ELF files); Mesa's EGL and GL drivers are
# loaded at run time through libglvnd, not linked, so they are listed by hand.
set(CPACK_PACKAGE_NAME shadowtune)
set(CPACK_PACKAGE_VENDOR "shadowtune")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Tune cascaded shadow maps: OpenGL 4.5 editor, headless EGL replay, CSM math library")
set(CPACK_PACKAGE_CONTACT "shadowtune maintainers <shadowtune@localhost>")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The charts' and labels' fonts (report/chart_fonts.h) are named, not linked: no shlibdeps finds them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri, fonts-dejavu-core")
# find_package(shadowtune) needs GLM's headers and CMake package.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libglm-dev")
# The editor under X11 draws through GLX; with Mesa that is libglx-mesa0.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libglx-mesa0")
include(CPack)
