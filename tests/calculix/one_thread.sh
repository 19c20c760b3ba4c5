# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the tier's scripts before they run ccx: one thread, since two change ccx's own
# results by ~1e-7 (OpenMP and its CCX_NPROC_* pools).
export OMP_NUM_THREADS=1 NUMBER_OF_PROCESSORS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_RESULTS=1 \
       CCX_NPROC_EQUATION_SOLVER=1 CCX_NPROC_CFD=1 CCX_NPROC_BIOTSAVART=1 CCX_NPROC_SENS=1
