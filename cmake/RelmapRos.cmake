# ROS 1 as Debian 12 ships it (ros-core-dev, librosbag-dev, libtf2-ros-dev, ...; see
# scripts/install-deps.sh), for robot_adapter/ros. RELMAP_WITH_ROS is AUTO by default:
# on when every piece is found, off with a message naming the missing one otherwise.
# ROS 1's packages on Debian have pkg-config files, but rosbag_storage's names
# pluginlib, whose Debian package has none: rosbag and the pluginlib headers it
# includes are looked up by hand.
set(RELMAP_WITH_ROS AUTO CACHE STRING "Build the ROS 1 bridge: ON, OFF or AUTO (when found)")
set_property(CACHE RELMAP_WITH_ROS PROPERTY STRINGS AUTO ON OFF)

function(relmap_find_ros result missing)
  find_package(PkgConfig QUIET)
  if(NOT PkgConfig_FOUND)
    set(${missing} "pkg-config" PARENT_SCOPE)
    return()
  endif()
  pkg_check_modules(RELMAP_ROS1 QUIET IMPORTED_TARGET GLOBAL roscpp tf2_ros rostime)
  if(NOT RELMAP_ROS1_FOUND)
    set(${missing} "roscpp/tf2_ros (pkg-config)" PARENT_SCOPE)
    return()
  endif()
  find_library(RELMAP_ROSBAG_LIBRARY rosbag)
  find_library(RELMAP_ROSBAG_STORAGE_LIBRARY rosbag_storage)
  find_library(RELMAP_CLASS_LOADER_LIBRARY class_loader)
  find_path(RELMAP_PLUGINLIB_INCLUDE_DIR pluginlib/class_loader.hpp PATH_SUFFIXES pluginlib)
  find_path(RELMAP_CLASS_LOADER_INCLUDE_DIR class_loader/class_loader.hpp
            PATH_SUFFIXES class_loader)
  # pluginlib and class_loader on Debian 12 are ROS 2's, in folders of their own.
  find_path(RELMAP_RCPPUTILS_INCLUDE_DIR rcpputils/shared_library.hpp PATH_SUFFIXES rcpputils)
  find_path(RELMAP_RCUTILS_INCLUDE_DIR rcutils/types.h PATH_SUFFIXES rcutils)
  find_path(RELMAP_AMENT_INDEX_INCLUDE_DIR ament_index_cpp/get_resource.hpp
            PATH_SUFFIXES ament_index_cpp)
  find_path(RELMAP_ROS_MSGS_INCLUDE_DIR sensor_msgs/PointCloud2.h)
  find_path(RELMAP_ROS_MSG_DEFINITIONS std_msgs/msg/Header.msg PATHS /usr/share)
  find_file(RELMAP_GENCPP gen_cpp.py PATHS /usr/lib/gencpp NO_DEFAULT_PATH)
  foreach(piece RELMAP_ROSBAG_LIBRARY RELMAP_ROSBAG_STORAGE_LIBRARY RELMAP_CLASS_LOADER_LIBRARY
                RELMAP_PLUGINLIB_INCLUDE_DIR RELMAP_CLASS_LOADER_INCLUDE_DIR
                RELMAP_RCPPUTILS_INCLUDE_DIR RELMAP_RCUTILS_INCLUDE_DIR
                RELMAP_AMENT_INDEX_INCLUDE_DIR
                RELMAP_ROS_MSGS_INCLUDE_DIR RELMAP_ROS_MSG_DEFINITIONS RELMAP_GENCPP)
    if(NOT ${piece})
      set(${missing} "${piece}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  # gencpp runs on the system's Python, which has Debian's genmsg (a virtualenv's may not).
  find_program(RELMAP_ROS_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
  if(RELMAP_ROS_PYTHON)
    execute_process(COMMAND ${RELMAP_ROS_PYTHON} -c "import genmsg, gencpp"
                    RESULT_VARIABLE import_failed OUTPUT_QUIET ERROR_QUIET)
  endif()
  if(NOT RELMAP_ROS_PYTHON OR import_failed)
    set(${missing} "python3-genmsg/python3-gencpp" PARENT_SCOPE)
    return()
  endif()
  set(${result} TRUE PARENT_SCOPE)
endfunction()

set(RELMAP_ROS_ENABLED FALSE)
if(NOT RELMAP_WITH_ROS STREQUAL "OFF")
  relmap_find_ros(relmap_ros_found relmap_ros_missing)
  if(relmap_ros_found)
    set(RELMAP_ROS_ENABLED TRUE)
    message(STATUS "ROS 1 bridge: on (relmap_ros_bridge, relmap_ros_replay)")
  elseif(RELMAP_WITH_ROS STREQUAL "ON")
    message(FATAL_ERROR "RELMAP_WITH_ROS=ON, but ${relmap_ros_missing} is missing: "
                        "scripts/install-deps.sh installs ROS 1")
  else()
    message(STATUS "ROS 1 bridge: off, ${relmap_ros_missing} not found "
                   "(scripts/install-deps.sh installs ROS 1)")
  endif()
else()
  message(STATUS "ROS 1 bridge: off (RELMAP_WITH_ROS=OFF)")
endif()
