# relmap_sim_runner and relmap-sim: the experiment runner. It talks to relmap-server
# over the wire only (client library, proto API) and scores maps with common/metrics.h
# (pure maths); it includes no header of server/.
add_library(relmap_sim_runner STATIC
  body_labels.cpp
  curves.cpp
  dataset_csv.cpp
  dataset_frame.cpp
  dataset_options.cpp
  experiment.cpp
  experiment_options.cpp
  flags.cpp
  ground_truth.cpp
  learned_samples.cpp
  map_snapshots.cpp
  packed_cloud.cpp
  physical_dataset.cpp
  plots.cpp
  replication.cpp
  scene_loading.cpp
  server_connection.cpp
  spread.cpp
  target_choice.cpp)
target_include_directories(relmap_sim_runner PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(relmap_sim_runner
  PUBLIC relmap_client relmap_client_rendering relmap_common relmap_image relmap_proto
         Eigen3::Eigen
  PRIVATE relmap_local_server Threads::Threads relmap_warnings)
# The ODE world (world.cmake) once it exists: scene_loading.cpp then loads its scenes.
if(TARGET relmap_sim_world)
  target_link_libraries(relmap_sim_runner PUBLIC relmap_sim_world)
  target_compile_definitions(relmap_sim_runner PRIVATE RELMAP_SIM_WITH_WORLD=1)
endif()

add_executable(relmap-sim relmap_sim_main.cpp run_command.cpp dataset_command.cpp)
target_link_libraries(relmap-sim PRIVATE relmap_sim_runner relmap_local_server relmap_warnings)
if(TARGET relmap_sim_scene_commands)
  target_link_libraries(relmap-sim PRIVATE relmap_sim_scene_commands)
  target_compile_definitions(relmap-sim PRIVATE RELMAP_SIM_WITH_SCENE_COMMANDS=1)
endif()
add_dependencies(relmap-sim relmap-server)
