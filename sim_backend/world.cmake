# relmap_sim_world: scene files (JSON; schema in scene_schema.proto), the ODE
# world, the ray-cast RGB-D camera and the push primitive. It links no server
# library: the simulator talks to relmap-server over the wire only.

# The scene-file schema, generated at build time.
add_library(relmap_sim_scene_proto STATIC scene_schema.proto)
target_link_libraries(relmap_sim_scene_proto PUBLIC protobuf::libprotobuf)
target_include_directories(relmap_sim_scene_proto SYSTEM PUBLIC ${CMAKE_CURRENT_BINARY_DIR})
protobuf_generate(TARGET relmap_sim_scene_proto
                  IMPORT_DIRS ${CMAKE_CURRENT_SOURCE_DIR}
                  PROTOC_OUT_DIR ${CMAKE_CURRENT_BINARY_DIR})

add_library(relmap_sim_world STATIC
  scene_settings.cpp scene_validation.cpp scene_file.cpp seeded_random.cpp textures.cpp
  kinect_noise_model.cpp ode_world.cpp ode_bodies.cpp ray_casting.cpp ray_camera.cpp
  structured_light_camera.cpp point_distance.cpp scene_dynamics.cpp
  visible_motion.cpp push_primitive.cpp ode_scene.cpp)
target_include_directories(relmap_sim_world PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(relmap_sim_world
  PRIVATE RELMAP_SIM_SCENES_DIR="${CMAKE_CURRENT_SOURCE_DIR}/scenes")
target_link_libraries(relmap_sim_world
  PUBLIC relmap_common relmap_sim_scene_proto Eigen3::Eigen PkgConfig::ODE
  PRIVATE protobuf::libprotobuf Threads::Threads relmap_warnings)

# `relmap-sim scenes` and `relmap-sim render`, for the runner's executable.
add_library(relmap_sim_scene_commands STATIC scene_commands.cpp)
target_link_libraries(relmap_sim_scene_commands
  PUBLIC relmap_sim_world PRIVATE relmap_image relmap_warnings)
