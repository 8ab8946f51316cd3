# GEOMCHECK_VERSION: the project's version with `git describe` of the source
# tree at configure time (the release number alone where there is no git);
# `geomcheck --version` and verify()'s reports say it.
find_package(Git QUIET)
set(GEOMCHECK_VERSION "${PROJECT_VERSION}")
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                  OUTPUT_VARIABLE git_describe OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE git_rc)
  if(git_rc EQUAL 0 AND git_describe)
    set(GEOMCHECK_VERSION "${PROJECT_VERSION} (${git_describe})")
  endif()
endif()
