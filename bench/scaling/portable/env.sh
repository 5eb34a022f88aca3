#------------------------------------------------------------------------------
# flapFoam portable runtime: the environment of the unpacked archive
# (bench/scaling/pack), sourced by its runTimed.  Everything the runs load
# comes from the archive's rt/ folder but glibc (libc, libm, libdl,
# libpthread, librt, libresolv and the loader: the host's, 2.36 or newer):
# OpenFOAM v1912's binaries, libraries and etc/, the project's libraries,
# Open MPI 4.1.4 (orterun, orted, plugins, help files) and PMIx, relocated
# with their OPAL_* and PMIX_* prefix variables; one node without ssh
# (plm isolated), shared memory (btl self,vader).
#------------------------------------------------------------------------------
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
#------------------------------------------------------------------------------
portableRoot="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)"
rt="$portableRoot/rt"

export PATH="$rt/bin:$rt/mpi/bin:$PATH"
export LD_LIBRARY_PATH="$rt/lib"
export WM_PROJECT=OpenFOAM WM_PROJECT_VERSION=v1912
export WM_PROJECT_DIR="$rt/openfoam"
export FOAM_ETC="$rt/openfoam/etc"

# Open MPI: Debian's was built for /usr, its /etc/openmpi absolute
mpi="$rt/mpi"
export OPAL_PREFIX="$mpi" OPAL_EXEC_PREFIX="$mpi"
export OPAL_BINDIR="$mpi/bin" OPAL_SBINDIR="$mpi/bin"
export OPAL_LIBEXECDIR="$mpi/bin"
export OPAL_LIBDIR="$mpi/lib/x86_64-linux-gnu/openmpi/lib"
export OPAL_PKGLIBDIR="$OPAL_LIBDIR/openmpi3"
export OPAL_DATAROOTDIR="$mpi/share" OPAL_DATADIR="$mpi/share"
export OPAL_PKGDATADIR="$mpi/share/openmpi"
export OPAL_SYSCONFDIR="$mpi/etc"
pmix="$rt/pmix"
export PMIX_PREFIX="$pmix" PMIX_INSTALL_PREFIX="$pmix"
export PMIX_EXEC_PREFIX="$pmix" PMIX_LIBDIR="$pmix/lib"
export PMIX_PKGLIBDIR="$pmix/lib/pmix"
export PMIX_DATAROOTDIR="$pmix/share" PMIX_DATADIR="$pmix/share"
export PMIX_PKGDATADIR="$pmix/share/pmix" PMIX_SYSCONFDIR="$pmix/share"
export PMIX_MCA_gds=hash
export HWLOC_PLUGINS_PATH="$rt/hwloc-plugins"

export OMPI_MCA_plm=isolated OMPI_MCA_btl=self,vader
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
unset portableRoot mpi pmix
#------------------------------------------------------------------------------
