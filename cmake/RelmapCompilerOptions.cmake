# Warnings for the project's own targets. No -march flags: Debian's PCL is built
# for generic x86-64, and mismatched Eigen alignment has crashed SupervoxelClustering.
add_library(relmap_warnings INTERFACE)
target_compile_options(relmap_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion)

# GNU gold (binutils, no extra package) links the programs that pull in PCL, whose
# libraries bring ~100 VTK shared objects, an order of magnitude faster than ld.bfd:
# fuzz_replay_service links in 0.8 s instead of 10.5 s. Linking was ~230 s of the
# 1,650 s of compiler time a clean build takes on 2 cores (docs/toolchain.md).
include(CheckLinkerFlag)
check_linker_flag(CXX -fuse-ld=gold RELMAP_LINKER_GOLD)
if(RELMAP_LINKER_GOLD)
  add_link_options(-fuse-ld=gold)
endif()
