# The registered query ids, read from the registry itself
# (core/include/geomcheck/registry.hpp), so that no list of queries is typed
# in a build file. Reconfigures when the registry changes.
#   geomcheck_query_ids(PAIRS POINT_SETS): the ids of GEOMCHECK_QUERY_LIST
#   (two shapes) and of GEOMCHECK_POINTSET_QUERY_LIST (a point set).
function(geomcheck_query_ids pairs_out point_sets_out)
  set(registry ${PROJECT_SOURCE_DIR}/core/include/geomcheck/registry.hpp)
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${registry})
  file(READ ${registry} text)
  # Each list is a macro (its lines end in backslashes): its X(id, ...)
  # entries up to the first line without one.
  foreach(list GEOMCHECK_QUERY_LIST GEOMCHECK_POINTSET_QUERY_LIST)
    string(FIND "${text}" "#define ${list}(X)" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${list} not found in ${registry}")
    endif()
    string(SUBSTRING "${text}" ${at} -1 rest)
    string(REGEX MATCH "#define ${list}\\(X\\)([^\n]*\\\\\n)*[^\n]*\n" body "${rest}")
    string(REGEX MATCHALL "\n  X\\([a-z0-9_]+," entries "${body}")
    set(ids_${list})
    foreach(entry IN LISTS entries)
      string(REGEX REPLACE "\n  X\\(([a-z0-9_]+)," "\\1" id "${entry}")
      list(APPEND ids_${list} ${id})
    endforeach()
    if(NOT ids_${list})
      message(FATAL_ERROR "no query ids found in ${list} of ${registry}")
    endif()
  endforeach()
  set(${pairs_out} ${ids_GEOMCHECK_QUERY_LIST} PARENT_SCOPE)
  set(${point_sets_out} ${ids_GEOMCHECK_POINTSET_QUERY_LIST} PARENT_SCOPE)
endfunction()
