# SPDX-License-Identifier: GPL-3.0-or-later
# The CalculiX tier (label calculix, tests/calculix/README.md): CalculiX's penalty-contact
# friction computed by fricreg's element kernel, against stock ccx 2.20. Registered with
# -DFRICREG_CALCULIX=ON only: it fetches and builds ccx (about 8 minutes on two cores) and is
# neither in the quick tier nor in .ci/run. Included from tests/CMakeLists.txt.
option(FRICREG_CALCULIX "Register the CalculiX tier (ctest -L calculix): builds ccx 2.20 privately" OFF)
if(NOT FRICREG_CALCULIX)
  return()
endif()
set(FRICREG_CCX_DIR ${CMAKE_CURRENT_BINARY_DIR}/calculix)
set(FRICREG_CCX_SRC ${PROJECT_SOURCE_DIR}/tests/calculix)
# Debian's calculix-ccx-test 2.11: its decks with *FRICTION (test calculix_decks holds the
# package to this list).
set(FRICREG_CCX_TESTS /usr/share/doc/calculix-ccx-test/examples/test)
if(NOT IS_DIRECTORY ${FRICREG_CCX_TESTS})
  message(FATAL_ERROR "FRICREG_CALCULIX=ON: no ${FRICREG_CCX_TESTS} (Debian: apt-get install "
                      "calculix-ccx-test; README.md has the tier's whole command)")
endif()
set(FRICREG_CCX_DECKS beamptied5 beamptied6 beamptied7 changefric changesurfbeh cubef2f1
    cubef2f2 cubef2f3 fricloop friction1 friction2 metalforming metalformingmortar
    ringfcontact1 ringfcontact3 ringfcontact4 ringfcontact5)
# fricreg's own: slip on both routines along a turning path
set(FRICREG_CCX_OWN_DECKS slipn2f slipf2f)

# The set-up: the source, the stock and the patched ccx, fricreg's hook frccx.c linked into
# the patched one (fixture calculix).
add_test(NAME calculix_build
         COMMAND sh ${FRICREG_CCX_SRC}/build.sh ${FRICREG_CCX_DIR} ${FRICREG_CCX_SRC}/ccx-fricreg.patch
                 ${FRICREG_CCX_SRC}/frccx.c ${PROJECT_SOURCE_DIR}/include
                 ${PROJECT_BINARY_DIR}/include $<TARGET_LINKER_FILE_DIR:fricreg>)
# debian/rules builds with two jobs: ctest -j2 counts the test as two.
set_tests_properties(calculix_build PROPERTIES LABELS calculix FIXTURES_SETUP calculix
                     TIMEOUT 2400 PROCESSORS 2)
# What the patched ccx asks of fricreg, counted through LD_PRELOAD (compare.sh prints it).
add_library(fricreg_ccx_counts MODULE ${FRICREG_CCX_SRC}/count_calls.c)
target_link_libraries(fricreg_ccx_counts PRIVATE fricreg ${CMAKE_DL_LIBS} m)
target_compile_options(fricreg_ccx_counts PRIVATE ${FRICREG_WARNINGS})
add_test(NAME calculix_decks
         COMMAND sh ${FRICREG_CCX_SRC}/decks.sh ${FRICREG_CCX_TESTS} ${FRICREG_CCX_DECKS})
set_tests_properties(calculix_decks PROPERTIES LABELS calculix TIMEOUT 60)
foreach(deck IN LISTS FRICREG_CCX_DECKS FRICREG_CCX_OWN_DECKS)
  if(deck IN_LIST FRICREG_CCX_OWN_DECKS)
    set(file ${FRICREG_CCX_SRC}/decks/${deck}.inp)
  else()
    set(file ${FRICREG_CCX_TESTS}/${deck}.inp)
    if(NOT EXISTS ${file})
      set(file ${file}.gz)
    endif()
  endif()
  # every interaction on fricreg's jenkins_3d: stock's answers through the kernel
  add_test(NAME calculix_${deck}
           COMMAND sh ${FRICREG_CCX_SRC}/compare.sh ${FRICREG_CCX_DIR} ${file}
                   ${FRICREG_CCX_DIR}/runs/${deck} ${FRICREG_CCX_SRC}/decks/coulomb.fricreg)
  set_tests_properties(calculix_${deck} PROPERTIES LABELS calculix FIXTURES_REQUIRED calculix
                       TIMEOUT 600
                       ENVIRONMENT FRICREG_CCX_COUNTER=$<TARGET_FILE:fricreg_ccx_counts>)
  # no laws file: ccx's own code, stock's bytes
  add_test(NAME calculix_${deck}_unnamed
           COMMAND sh ${FRICREG_CCX_SRC}/compare.sh ${FRICREG_CCX_DIR} ${file}
                   ${FRICREG_CCX_DIR}/runs/${deck}_unnamed -)
  set_tests_properties(calculix_${deck}_unnamed PROPERTIES LABELS calculix
                       FIXTURES_REQUIRED calculix TIMEOUT 600
                       ENVIRONMENT FRICREG_CCX_COUNTER=$<TARGET_FILE:fricreg_ccx_counts>)
endforeach()

# The Iwan deck: fricreg's Iwan law in ccx (its laws file decks/iwanloop.fricreg) against
# the kernel driven alone on the history ccx printed (iwan_alone.c, fricreg only, never ccx):
# the hysteresis loops' dissipations to 1e-6, and the loops plotted (iwan.sh says where).
add_executable(fricreg_ccx_iwan_alone ${FRICREG_CCX_SRC}/iwan_alone.c)
target_link_libraries(fricreg_ccx_iwan_alone PRIVATE fricreg m)
target_compile_options(fricreg_ccx_iwan_alone PRIVATE ${FRICREG_WARNINGS})
add_test(NAME calculix_iwan
         COMMAND sh ${FRICREG_CCX_SRC}/iwan.sh ${FRICREG_CCX_DIR}
                 ${FRICREG_CCX_SRC}/decks/iwanloop.inp ${FRICREG_CCX_SRC}/decks/iwanloop.fricreg
                 ${FRICREG_CCX_DIR}/runs/iwanloop
                 $<TARGET_FILE:fricreg_ccx_iwan_alone>)
set_tests_properties(calculix_iwan PROPERTIES LABELS calculix FIXTURES_REQUIRED calculix
                     TIMEOUT 600)

# The closed-form deck: two contact pairs on two laws (jenkins_3d, iwan_3d 5) in one ccx, node
# to surface and surface to surface, each loop's dissipation at three amplitudes against its
# closed form to 1e-3, and closer at half the increment (closed_form.sh).
add_test(NAME calculix_closed_form
         COMMAND sh ${FRICREG_CCX_SRC}/closed_form.sh ${FRICREG_CCX_DIR}
                 ${FRICREG_CCX_SRC}/decks/iwanclosed.inp
                 ${FRICREG_CCX_SRC}/decks/iwanclosed.fricreg
                 ${FRICREG_CCX_DIR}/runs/iwanclosed)
set_tests_properties(calculix_closed_form PROPERTIES LABELS calculix FIXTURES_REQUIRED calculix
                     TIMEOUT 600)

# A laws file the patched ccx cannot follow: refused with its reason (laws_errors.sh).
add_test(NAME calculix_laws_errors
         COMMAND sh ${FRICREG_CCX_SRC}/laws_errors.sh ${FRICREG_CCX_DIR}
                 ${FRICREG_CCX_SRC}/decks/iwanclosed.inp ${FRICREG_CCX_DIR}/runs/laws_errors)
set_tests_properties(calculix_laws_errors PROPERTIES LABELS calculix FIXTURES_REQUIRED calculix
                     TIMEOUT 600)
