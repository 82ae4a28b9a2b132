# Tests of the runner and relmap-sim, on an analytic test double of the world
# (analytic_scene.h): unit tests of its pieces, and runs against a real server.
add_library(relmap_sim_analytic_scene STATIC analytic_scene.cpp)
target_include_directories(relmap_sim_analytic_scene PUBLIC ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(relmap_sim_analytic_scene PUBLIC relmap_sim_runner PRIVATE relmap_warnings)

relmap_add_gtest(sim_runner_test
  SOURCES analytic_scene_test.cpp curves_test.cpp dataset_options_test.cpp
          experiment_options_test.cpp
          body_labels_test.cpp ground_truth_test.cpp learned_samples_test.cpp
          packed_cloud_test.cpp target_choice_test.cpp
  LIBRARIES relmap_sim_analytic_scene relmap_sim_runner
  LABELS unit)

relmap_add_gtest(sim_runner_end_to_end_test
  SOURCES runner_end_to_end_test.cpp
  LIBRARIES relmap_sim_analytic_scene relmap_sim_runner relmap_local_server relmap_integration_support
  LABELS integration)
target_compile_definitions(sim_runner_end_to_end_test PRIVATE
  RELMAP_SERVER_BINARY="$<TARGET_FILE:relmap-server>")
add_dependencies(sim_runner_end_to_end_test relmap-server)

# The acceptance run on the paper's MoveableBalls scene: it needs the ODE world, and
# switches itself on once world.cmake defines relmap_sim_world.
if(TARGET relmap_sim_world)
  relmap_add_gtest(sim_moveable_balls_test
    SOURCES moveable_balls_test.cpp
    LIBRARIES relmap_sim_runner relmap_local_server relmap_integration_support
    LABELS slow)
  target_compile_definitions(sim_moveable_balls_test PRIVATE
    RELMAP_SERVER_BINARY="$<TARGET_FILE:relmap-server>")
  add_dependencies(sim_moveable_balls_test relmap-server)

  # relmap-sim dataset: same bytes for the same seed, a file relmap-cmm reads.
  add_test(NAME sim_dataset
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/dataset_test.sh $<TARGET_FILE:relmap-sim>
                   $<TARGET_FILE:relmap-cmm> $<TARGET_FILE:relmap-server>)
  set_tests_properties(sim_dataset PROPERTIES LABELS sim TIMEOUT 60)
endif()
