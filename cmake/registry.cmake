# The registered query ids, read from the registry itself
# (core/include/geomcheck/registry.hpp, one `X(id, ...)` line per query), so
# that no list of queries is typed in a build file. Reconfigures when the
# registry changes.
function(geomcheck_query_ids out)
  set(registry ${PROJECT_SOURCE_DIR}/core/include/geomcheck/registry.hpp)
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${registry})
  file(READ ${registry} text)
  # The lines end in backslashes (a macro): match the ids in the whole text.
  string(REGEX MATCHALL "\n  X\\([a-z0-9_]+," entries "${text}")
  set(ids)
  foreach(entry IN LISTS entries)
    string(REGEX REPLACE "\n  X\\(([a-z0-9_]+)," "\\1" id "${entry}")
    list(APPEND ids ${id})
  endforeach()
  if(NOT ids)
    message(FATAL_ERROR "no query ids found in ${registry}")
  endif()
  set(${out} ${ids} PARENT_SCOPE)
endfunction()
