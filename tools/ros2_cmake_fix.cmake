# Passed to cmake as -DCMAKE_PROJECT_INCLUDE by tools/setup_ros2.sh.
# The ROS 2 wheels' exported CMake targets still name the include directories of the
# machine they were built on (/opt/python/cp311-cp311/...). Once the top-level
# CMakeLists has run, drop every absolute include directory that does not exist from
# each imported target, so that cmake's generate step succeeds; Python's and numpy's real
# include directories still come from CMake's own Python3 targets.
function(robocram_drop_missing_include_directories)
  get_property(targets DIRECTORY "${CMAKE_SOURCE_DIR}" PROPERTY IMPORTED_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(directories ${target} INTERFACE_INCLUDE_DIRECTORIES)
    if(NOT directories)
      continue()
    endif()
    set(kept "")
    foreach(directory IN LISTS directories)
      if(IS_ABSOLUTE "${directory}" AND NOT EXISTS "${directory}"
         AND NOT directory MATCHES "^\\$<")
        continue()
      endif()
      list(APPEND kept "${directory}")
    endforeach()
    set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${kept}")
  endforeach()
endfunction()
cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL robocram_drop_missing_include_directories)
