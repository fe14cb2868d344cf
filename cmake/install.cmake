# `cmake --install build --prefix P`: the public headers in P/include/akvf, the
# libraries, the `akvf` program, and the CMake package akvf (config, version
# file, targets akvf::akvf and its parts) so that another project can write
#   find_package(akvf 0.2 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE akvf::akvf)
include(CMakePackageConfigHelpers)
set(AKVF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/akvf)

foreach(part headers framework io energies solvers preconditioners pictures)
  set_target_properties(akvf_${part} PROPERTIES EXPORT_NAME ${part})
endforeach()
install(TARGETS akvf_headers akvf_framework akvf_io akvf_energies akvf_solvers akvf_preconditioners akvf_api
  akvf_pictures akvf_library
  EXPORT akvfTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS akvf RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The public headers alone, at include/akvf/*.h; akvf/internal/ and the
# library folders (framework/, energies/, ...) stay in the source tree.
file(GLOB akvf_public_headers ${PROJECT_SOURCE_DIR}/akvf/*.h)
install(FILES ${akvf_public_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/akvf)

install(EXPORT akvfTargets NAMESPACE akvf:: DESTINATION ${AKVF_CMAKE_DIR})
configure_package_config_file(cmake/akvfConfig.cmake.in ${PROJECT_BINARY_DIR}/akvfConfig.cmake
  INSTALL_DESTINATION ${AKVF_CMAKE_DIR})
# 0.x: a minor version may change the API, so 0.2 accepts 0.2.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/akvfConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/akvfConfig.cmake ${PROJECT_BINARY_DIR}/akvfConfigVersion.cmake
  cmake/FindCHOLMOD.cmake cmake/FindHYPRE.cmake DESTINATION ${AKVF_CMAKE_DIR})
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/akvf)
