# install rules (README "Install"): cmake --install build --prefix P puts
#   lib/libmjbuoy.so.<version> (+ .so.<major>, .so), lib/libmjbuoy.a with MJBUOY_BUILD_STATIC
#   include/mjbuoy/{mjbuoy.h,mjbuoy_version.h}   the public header only
#   bin/mjbuoy-*                                   every tool target of tools/
#   share/mjbuoy/models/                           the example scenes and meshes
#   share/doc/mjbuoy/                              README, CHANGELOG and docs/*.md
#   lib/cmake/mjbuoy/                              find_package(mjbuoy CONFIG): mjbuoy::mjbuoy
#   lib/pkgconfig/mjbuoy.pc                        pkg-config --cflags --libs mjbuoy
include(CMakePackageConfigHelpers)
set(mjb_cmakedir ${CMAKE_INSTALL_LIBDIR}/cmake/mjbuoy)

set(mjb_targets "")
if(MJBUOY_BUILD_SHARED)
  list(APPEND mjb_targets mjbuoy_shared)
endif()
if(MJBUOY_BUILD_STATIC)
  list(APPEND mjb_targets mjbuoy)
endif()
install(TARGETS ${mjb_targets} EXPORT mjbuoyTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/mjbuoy/mjbuoy.h
  ${PROJECT_BINARY_DIR}/include/mjbuoy/mjbuoy_version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mjbuoy)
install(EXPORT mjbuoyTargets NAMESPACE mjbuoy:: DESTINATION ${mjb_cmakedir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/mjbuoyConfig.cmake.in
  ${PROJECT_BINARY_DIR}/mjbuoyConfig.cmake INSTALL_DESTINATION ${mjb_cmakedir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mjbuoyConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mjbuoyConfig.cmake ${PROJECT_BINARY_DIR}/mjbuoyConfigVersion.cmake
  DESTINATION ${mjb_cmakedir})

# pkg-config: MuJoCo ships no .pc on Debian, so its library goes in Libs
get_target_property(mjb_mujoco_lib mujoco::mujoco LOCATION)
get_filename_component(mjb_mujoco_libdir ${mjb_mujoco_lib} DIRECTORY)
get_target_property(mjb_mujoco_inc mujoco::mujoco INTERFACE_INCLUDE_DIRECTORIES)
set(MJB_PC_CFLAGS "")
foreach(d ${mjb_mujoco_inc})
  if(EXISTS ${d}/mujoco/mujoco.h AND NOT d MATCHES "^/usr/include/?$")
    string(APPEND MJB_PC_CFLAGS " -I${d}")
  endif()
endforeach()
set(MJB_PC_MUJOCO "-L${mjb_mujoco_libdir} -lmujoco")
if(mjb_mujoco_libdir MATCHES "^/usr/lib")
  set(MJB_PC_MUJOCO "-lmujoco")
endif()
# relocatable: the prefix is found from the .pc file's own place, so
# cmake --install --prefix P works whatever CMAKE_INSTALL_PREFIX was
file(RELATIVE_PATH MJB_PC_UP /x/${CMAKE_INSTALL_LIBDIR}/pkgconfig /x)
string(REGEX REPLACE "/$" "" MJB_PC_UP "${MJB_PC_UP}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/mjbuoy.pc.in ${PROJECT_BINARY_DIR}/mjbuoy.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/mjbuoy.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/ DESTINATION ${CMAKE_INSTALL_DATADIR}/mjbuoy/models)
# the README's links (docs/*.md, CHANGELOG.md) resolve in the installed tree:
# docs/ keeps its name beside README.md (the Markdown sources of the site)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
  DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
  FILES_MATCHING PATTERN "*.md")

# every executable target of tools/ (so tools added later install too)
if(MJBUOY_BUILD_TOOLS)
  get_property(mjb_tools DIRECTORY ${PROJECT_SOURCE_DIR}/tools PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t ${mjb_tools})
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "EXECUTABLE")
      install(TARGETS ${t} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
    endif()
  endforeach()
endif()
