"""setuptools' build of the relmap package: before the sources are copied into the
wheel, the stubs are generated from the repository's proto/ by generate_stubs.py, the
generator the CMake build runs (client/python/CMakeLists.txt)."""

import os
import sys

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
PROTO_DIR = os.environ.get("RELMAP_PROTO_DIR", os.path.join(HERE, "..", "..", "proto"))


class BuildWithStubs(build_py):
    """build_py that writes relmap/v1 and relmap/_rpc into the build directory first."""

    def run(self):
        sys.path.insert(0, HERE)
        from generate_stubs import generate

        if not os.path.isdir(PROTO_DIR):
            raise SystemExit(f"relmap: no proto directory at {PROTO_DIR} (set RELMAP_PROTO_DIR)")
        generate(PROTO_DIR, self.build_lib)
        super().run()

    def find_package_modules(self, package, package_dir):
        # relmap/v1 and relmap/_rpc exist only in the build directory: nothing to copy.
        if package in ("relmap.v1", "relmap._rpc"):
            return []
        return super().find_package_modules(package, package_dir)

    def check_package(self, package, package_dir):
        if package in ("relmap.v1", "relmap._rpc"):
            return None
        return super().check_package(package, package_dir)


setup(cmdclass={"build_py": BuildWithStubs})
