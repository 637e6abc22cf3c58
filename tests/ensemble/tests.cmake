# Interrupts and ensembles (issue 19). Included by tests/CMakeLists.txt, which defines GP_BIN.

# simulate, oracle and view stopped by SIGTERM or SIGINT while writing: the partial file removed,
# the older output kept, one line, exit 143 or 130. Long runs, so that the signal comes mid-run.
set(GP_INTERRUPT ${CMAKE_CURRENT_SOURCE_DIR}/ensemble/interrupt_removes_partial.sh)
add_test(NAME cli.simulate_sigterm_removes_the_partial_file
         COMMAND sh ${GP_INTERRUPT} TERM 143 interrupted_simulate.csv ${GP_BIN} simulate
                 ${CMAKE_SOURCE_DIR}/scenes/rain1000.json --duration 1000)
add_test(NAME cli.oracle_sigint_removes_the_partial_file
         COMMAND sh ${GP_INTERRUPT} INT 130 interrupted_oracle.csv ${GP_BIN} oracle
                 ${CMAKE_SOURCE_DIR}/scenes/orbit.json --duration 1e6 --output-dt 1000)
add_test(NAME cli.view_sigterm_removes_the_partial_file
         COMMAND sh ${GP_INTERRUPT} TERM 143 interrupted_view.html ${GP_BIN} view
                 ${CMAKE_SOURCE_DIR}/scenes/rain1000.json --duration 1000)

target_link_libraries(gamephysics_tests PRIVATE gamephysics_ensemble)
