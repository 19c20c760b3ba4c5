# SPDX-License-Identifier: GPL-3.0-or-later
# Loaded by project() (CMAKE_USER_MAKE_RULES_OVERRIDE_C, set in CMakeLists.txt) after CMake's
# own compiler defaults and before they become cache entries, so -DCMAKE_C_FLAGS_<CONFIG>=...
# still wins. The default build type RelWithDebInfo gets -O3 where CMake gives -O2: at -O2
# GCC 12 vectorizes only loops whose trip count is a known multiple of the vector width (its
# "very cheap" cost model), none of the law kernels. Measured (bench/kernels.c, m = 10^3):
# fricreg_law_eval_batch 1.94 -> 0.93 ns/contact, fricreg_ctx_eval (W = I) 1.98 -> 1.39; a
# whole chain run (n = 1000, RK4) 0.78 -> 0.6-0.74 s. -g stays: the ABI check reads DWARF.
if(CMAKE_C_COMPILER_ID MATCHES "^(GNU|Clang|AppleClang)$")
  set(CMAKE_C_FLAGS_RELWITHDEBINFO_INIT "-O3 -g -DNDEBUG")
endif()
