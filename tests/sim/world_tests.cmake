# Tests of relmap_sim_world: scene files, the ray-cast camera, pushes, respawns,
# the shipped scenes, and the scenes/render commands.
relmap_add_gtest(sim_world_test
  SOURCES scene_file_test.cpp ray_camera_test.cpp push_test.cpp respawn_test.cpp
          shipped_scenes_test.cpp seeded_random_test.cpp scene_commands_test.cpp
          ideal_sensor_test.cpp kinect_noise_model_test.cpp structured_light_camera_test.cpp
          visible_motion_test.cpp
  LIBRARIES relmap_sim_world relmap_sim_scene_commands
  LABELS unit)
