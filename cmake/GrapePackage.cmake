# Install, export and package rules (GRAPE_INSTALL):
#  - the headers of the modules that were built, and the generated grape/config.hpp;
#  - the grape:: targets for find_package(grape), from the install tree and from the build
#    tree (grape_DIR=<build folder>);
#  - pkg-config files: grape.pc (the core) and grape-<module>.pc per optional module;
#  - CPack: `cpack -G DEB` in the build folder makes grape_<version>_<arch>.deb.
include(CMakePackageConfigHelpers)

# Headers: the whole folder (so a new core header needs no edit here) without the headers of
# optional modules that were not built.
set(excluded "")
foreach(module dynamics render scene)
  string(TOUPPER ${module} upper)
  if(NOT GRAPE_WITH_${upper})
    list(APPEND excluded PATTERN "${module}*.hpp" EXCLUDE)
  endif()
endforeach()
if(NOT GRAPE_WITH_SCENE)
  list(APPEND excluded PATTERN "sprite_sheet_json.hpp" EXCLUDE)  # read by the scene module
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/grape DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" ${excluded})
install(FILES ${PROJECT_BINARY_DIR}/include/grape/config.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/grape)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})

# CMake package.
set(GRAPE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/grape)
if(BUILD_SHARED_LIBS)
  set(GRAPE_SHARED ON)
else()
  set(GRAPE_SHARED OFF)
endif()
install(EXPORT grape-targets NAMESPACE grape:: DESTINATION ${GRAPE_CMAKE_DIR})
configure_package_config_file(cmake/grape-config.cmake.in ${PROJECT_BINARY_DIR}/grape-config.cmake
                              INSTALL_DESTINATION ${GRAPE_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/grape-config-version.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/grape-config.cmake ${PROJECT_BINARY_DIR}/grape-config-version.cmake
        DESTINATION ${GRAPE_CMAKE_DIR})
# The build tree as a package too: the same config next to a targets file that points into
# the source and build folders.
export(EXPORT grape-targets NAMESPACE grape:: FILE ${PROJECT_BINARY_DIR}/grape-targets.cmake)

# pkg-config. The prefix is found from the .pc file's own place, so an install under any
# --prefix (or a moved one) stays right.
set(GRAPE_PKGCONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(pc_prefix "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH to_prefix /${GRAPE_PKGCONFIG_DIR} /)
  string(REGEX REPLACE "/$" "" to_prefix "${to_prefix}")
  set(pc_prefix "\${pcfiledir}/${to_prefix}")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(pc_includedir "${CMAKE_INSTALL_INCLUDEDIR}")
else()
  set(pc_includedir "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(pc_libdir "${CMAKE_INSTALL_LIBDIR}")
else()
  set(pc_libdir "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
endif()

# grape_pkgconfig(NAME DESCRIPTION LIBS REQUIRES REQUIRES_PRIVATE)
function(grape_pkgconfig name description libs requires requires_private)
  set(PC_NAME ${name})
  set(PC_DESCRIPTION ${description})
  set(PC_LIBS ${libs})
  set(PC_REQUIRES ${requires})
  set(PC_REQUIRES_PRIVATE ${requires_private})
  # Users of a static library define GRAPE_NAME_STATIC, as its CMake target does (grape_module).
  set(PC_CFLAGS "")
  string(REGEX MATCHALL "-lgrape_[a-z]+" linked "${libs}")
  foreach(library IN LISTS linked)
    string(SUBSTRING ${library} 2 -1 library)
    get_target_property(type ${library} TYPE)
    if(type STREQUAL "STATIC_LIBRARY")
      string(REPLACE "grape_" "" module ${library})
      string(TOUPPER ${module} module)
      string(APPEND PC_CFLAGS " -DGRAPE_${module}_STATIC")
    endif()
  endforeach()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/grape.pc.in ${PROJECT_BINARY_DIR}/pkgconfig/${name}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/pkgconfig/${name}.pc DESTINATION ${GRAPE_PKGCONFIG_DIR})
endfunction()

# Static archives must be named in link order (a library before those it uses).
grape_pkgconfig(grape "${PROJECT_DESCRIPTION} (the core: math, path, curve, anim, bits, sprite)"
                "-lgrape_anim -lgrape_curve -lgrape_path -lgrape_bits -lgrape_sprite -lgrape_math" "" "")
if(GRAPE_WITH_DYNAMICS)
  grape_pkgconfig(grape-dynamics "grape's constrained particle dynamics" "-lgrape_dynamics" "grape" "")
endif()
if(GRAPE_WITH_RENDER)
  # A static grape_render needs cairo at the program's link; a shared one links it itself.
  if(BUILD_SHARED_LIBS)
    grape_pkgconfig(grape-render "grape's cairo drawing of paths, sprites and plots" "-lgrape_render" "grape" "cairo")
  else()
    grape_pkgconfig(grape-render "grape's cairo drawing of paths, sprites and plots" "-lgrape_render" "grape, cairo" "")
  endif()
endif()
if(GRAPE_WITH_SCENE)
  set(requires grape)
  if(GRAPE_WITH_DYNAMICS)
    set(requires "grape-dynamics, grape")
  endif()
  grape_pkgconfig(grape-scene "grape's JSON scenes" "-lgrape_scene" "${requires}" "")
endif()

# Debian package: libraries, headers, CMake and pkg-config files and the installed programs.
# Depends: the shared libraries the programs use (dpkg-shlibdeps: libcairo2, libstdc++6, ...)
# and, for a static grape_render, cairo's development files, which a program linking
# grape::render needs.
if(PROJECT_IS_TOP_LEVEL)
  set(CPACK_PACKAGE_NAME grape)
  set(CPACK_PACKAGE_VENDOR "The grape authors")
  set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
  set(CPACK_PACKAGE_DESCRIPTION "Paths and easing curves, an animation engine, constrained particle dynamics, bit vectors, sprite players, cairo rendering and JSON scenes: the libraries, headers, CMake and pkg-config files, and the grape command-line tool.")
  set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
  set(CPACK_DEBIAN_PACKAGE_MAINTAINER "The grape authors")
  set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
  set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  if(GRAPE_WITH_RENDER AND NOT BUILD_SHARED_LIBS)
    set(CPACK_DEBIAN_PACKAGE_DEPENDS "libcairo2-dev")
  endif()
  set(CPACK_SOURCE_IGNORE_FILES "/\\\\.git/" "/build[^/]*/")
  include(CPack)
endif()
