# Eigen 3.4 or 5.x, as circledist's CMakeLists.txt finds it: a given Eigen3_DIR as it is, otherwise
# one series at a time (the version file of Debian's Eigen 3.4.0 takes only 3.x requests, 5.x's
# only 5.x ones).
if(Eigen3_DIR AND EXISTS "${Eigen3_DIR}/Eigen3Config.cmake")
  find_package(Eigen3 NO_MODULE QUIET)
else()
  find_package(Eigen3 3.4 NO_MODULE QUIET)
  if(NOT Eigen3_FOUND)
    find_package(Eigen3 5 NO_MODULE QUIET)
  endif()
endif()
if(NOT Eigen3_FOUND OR Eigen3_VERSION VERSION_LESS 3.4)
  set(circledist_FOUND FALSE)
  string(CONCAT circledist_NOT_FOUND_MESSAGE "circledist needs Eigen 3.4 or 5.x and found neither (Debian: "
                "apt-get install libeigen3-dev; elsewhere set Eigen3_DIR or CMAKE_PREFIX_PATH)")
  return()
endif()
include("${CMAKE_CURRENT_LIST_DIR}/circledistTargets.cmake")
