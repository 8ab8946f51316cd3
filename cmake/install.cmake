# geomcheck — install rules and the package configuration
# (find_package(geomcheck CONFIG) from an out-of-tree project; see
# examples/verify-my-collide).
include(CMakePackageConfigHelpers)

set(GEOMCHECK_EXPORTED_TARGETS geomcheck_core geomcheck_oracles geomcheck_checks geomcheck_casefile geomcheck_reports
                               geomcheck_fuzzing)
set(GEOMCHECK_EXPORTED_INCLUDE_DIRS core/include oracles/include properties/include corpora/include reports/include
                                    fuzz/include)
set(GEOMCHECK_PACKAGE_HARNESS OFF)
if(TARGET geomcheck_subjects)
  list(APPEND GEOMCHECK_EXPORTED_TARGETS geomcheck_harness geomcheck_delaunay_oracle geomcheck_pointset_checks
       geomcheck_subjects)
  list(APPEND GEOMCHECK_EXPORTED_INCLUDE_DIRS subjects/include)
  set(GEOMCHECK_PACKAGE_HARNESS ON)
endif()
foreach(target IN LISTS GEOMCHECK_EXPORTED_TARGETS)
  string(REPLACE "geomcheck_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
endforeach()

install(TARGETS ${GEOMCHECK_EXPORTED_TARGETS} EXPORT geomcheckTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(dir IN LISTS GEOMCHECK_EXPORTED_INCLUDE_DIRS)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

set(GEOMCHECK_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/geomcheck)
install(EXPORT geomcheckTargets NAMESPACE geomcheck:: DESTINATION ${GEOMCHECK_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/geomcheckConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/geomcheckConfig.cmake INSTALL_DESTINATION ${GEOMCHECK_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/geomcheckConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/geomcheckConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/geomcheckConfigVersion.cmake
        DESTINATION ${GEOMCHECK_CMAKE_DIR})
