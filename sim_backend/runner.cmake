# relmap_sim_runner and relmap-sim: the experiment runner.
