# Tests of the runner and relmap-sim.
