# Tests of relmap_sim_world.
