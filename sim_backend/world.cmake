# relmap_sim_world: scene files, the ODE world, the camera and the push (see world.cmake's owner).
