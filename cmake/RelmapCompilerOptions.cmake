# Warnings for the project's own targets. No -march flags: Debian's PCL is built
# for generic x86-64, and mismatched Eigen alignment has crashed SupervoxelClustering.
add_library(relmap_warnings INTERFACE)
target_compile_options(relmap_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion)
