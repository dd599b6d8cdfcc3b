# shellcheck shell=bash
# Sourced by the build scripts (setup.sh, sanitize.sh, tsan.sh): the compiler cache, where
# Debian's ccache is installed. ccache keys each object by the compiler, every flag and the
# bytes of the source and of every header it reads, so a cached object is the one the same
# compile would make and any change misses; an empty cache costs only time. Most compiles
# carry the checkout's absolute path in a define (the built-in scene folder, the tests'
# SHADOWLAB_SOURCE_DIR), so the cache serves later builds of a checkout in the same folder:
# a developer's rebuilds, and CI's next run where it clones into the same place.
ccache_launcher=()
if command -v ccache > /dev/null; then
  export CCACHE_BASEDIR=$PWD CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-10G}
  ccache_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
