# Every third-party package comes from Debian (scripts/install-deps.sh). Each
# heavy group is looked up only when its option is on.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)  # Boost.Math is header-only
find_package(Threads REQUIRED)
find_package(spdlog REQUIRED)
find_package(fmt REQUIRED)  # spdlog's formatting library, used directly by the tools

if(RELMAP_WITH_PERCEPTION)
  find_package(PCL 1.13 REQUIRED COMPONENTS common io octree kdtree search features
               segmentation filters registration)
endif()

if(RELMAP_WITH_SERVER)
  # gRPC's CMake config (from protobuf-compiler-grpc) takes 0.2 s; the
  # pkg-config route costs ~15 s per configure.
  find_package(Protobuf REQUIRED)
  find_package(gRPC CONFIG REQUIRED)
  find_package(SQLite3 REQUIRED)
  # libpq (libpq-dev) for the shared session store; CMake's FindPostgreSQL needs
  # only the client headers.
  find_package(PostgreSQL REQUIRED)
endif()

if(RELMAP_WITH_SIM)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
  pkg_check_modules(YAML REQUIRED IMPORTED_TARGET yaml-0.1)  # relmap-robot's YAML configs
endif()

if(RELMAP_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(RELMAP_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
