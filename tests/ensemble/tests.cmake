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

# An ensemble of the bouncing ball for 2 s with the oracle: every sample's first impact at the
# closed form of its perturbed height, the engine within 1e-6 m of the oracle, the summary's
# mean and standard deviation those of the uniform draw (tests/ensemble/check_bouncing_ball.py).
add_test(NAME cli.ensemble_bouncing_ball_matches_the_closed_form
         COMMAND sh -c "rm -rf ens_ball && \"$0\" ensemble \"$1\"/scenes/bouncing_ball.json --duration 2 --samples 256 --oracle --out ens_ball --no-plots && python3 \"$1\"/tests/ensemble/check_bouncing_ball.py ens_ball 256"
                 ${GP_BIN} ${CMAKE_SOURCE_DIR})
# The same files to the byte on 1 and 2 threads (oblique collision, 100 samples, random sampler).
add_test(NAME cli.ensemble_same_bytes_on_1_and_2_threads
         COMMAND sh -c "rm -rf ens_t1 ens_t2 && for t in 1 2; do \"$0\" ensemble \"$1\"/scenes/oblique.json --samples 100 --sampler random --seed 5 --threads $t --out ens_t$t --no-plots > /dev/null || exit 1; done && for f in samples.csv energy.csv summary.json; do cmp ens_t1/$f ens_t2/$f || exit 1; done"
                 ${GP_BIN} ${CMAKE_SOURCE_DIR})
# Bad input: an uncertainty file with a spread out of range (exit 2, the message naming the file,
# the field, the rule and the value; no folder made), an unknown sampler.
add_test(NAME cli.ensemble_bad_uncertainty_exits_2_and_writes_nothing
         COMMAND sh -c "rm -rf ens_bad && printf '{\"mass\": 0.1, \"velocity\": 2}' > ens_bad_spreads.json && \"$0\" ensemble \"$1\"/scenes/bouncing_ball.json --samples 10 --uncertainty ens_bad_spreads.json --out ens_bad 2> ens_bad.txt; test $? -eq 2 && test \"$(cat ens_bad.txt)\" = \"error: ens_bad_spreads.json: velocity: must be a relative spread u with 0 <= u < 1, got 2\" && test ! -e ens_bad && \"$0\" ensemble \"$1\"/scenes/bouncing_ball.json --samples 10 --sampler halton --out ens_bad 2> ens_bad.txt; test $? -eq 2 && grep -qF 'sampler: must be sobol or random, got halton' ens_bad.txt && test ! -e ens_bad"
                 ${GP_BIN} ${CMAKE_SOURCE_DIR})
# A sample whose run fails (a non-finite state) is recorded with its error; the ensemble goes on.
add_test(NAME cli.ensemble_records_failed_samples
         COMMAND sh -c "rm -rf ens_fail && printf '{\"dt\": 0.01, \"duration\": 1, \"bodies\": [{\"name\": \"rocket\", \"position\": [0, 0], \"mass\": 1e-300, \"force\": [1e308, 0]}]}' > ens_fail.json && \"$0\" ensemble ens_fail.json --samples 40 --out ens_fail --no-plots && test $(grep -c \"has a non-finite state\" ens_fail/samples.csv) -eq 40 && grep -q '\"failed\": 40' ens_fail/summary.json"
                 ${GP_BIN})
# An ensemble killed midway resumes from its completed chunks to the bytes of a whole run.
add_test(NAME cli.ensemble_killed_resumes_to_the_same_bytes
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/ensemble/kill_and_resume.sh ${GP_BIN}
                 ${CMAKE_SOURCE_DIR}/scenes/bouncing_ball.json --samples 512 --threads 1 --no-plots)
# scenes/ensembles/rain100.json is what scenes/generate.py writes.
add_test(NAME scenes.generated_rain100_is_committed
         COMMAND sh -c "rm -rf generated_rain100 && python3 \"$0\"/scenes/generate.py generated_rain100 && diff generated_rain100/ensembles/rain100.json \"$0\"/scenes/ensembles/rain100.json"
                 ${CMAKE_SOURCE_DIR})
# Two MPI ranks (each on one thread) write the same files as one process (only with MPI built).
# Under the sanitizers (./test.sh), Open MPI's memory kept to the end is not ours to report:
# openmpi_leaks.supp names its libraries, which the slow unwinder is needed to see in the stacks.
if(GP_ENSEMBLE_MPIEXEC)
  add_test(NAME cli.ensemble_mpirun_matches_one_process
           COMMAND sh -c "rm -rf ens_mpi1 ens_mpi2 && ASAN_OPTIONS=\"\${ASAN_OPTIONS:+\$ASAN_OPTIONS:}fast_unwind_on_malloc=0\" LSAN_OPTIONS=suppressions=\"$3\" \"$0\" -np 2 --oversubscribe \"$1\" ensemble \"$2\"/scenes/bouncing_ball.json --duration 2 --samples 96 --threads 1 --out ens_mpi2 --no-plots > ens_mpi2.txt && grep -qF 'on 2 processes' ens_mpi2.txt && \"$1\" ensemble \"$2\"/scenes/bouncing_ball.json --duration 2 --samples 96 --threads 1 --out ens_mpi1 --no-plots > /dev/null && for f in samples.csv energy.csv summary.json; do cmp ens_mpi1/$f ens_mpi2/$f || exit 1; done"
                   ${GP_ENSEMBLE_MPIEXEC} ${GP_BIN} ${CMAKE_SOURCE_DIR}
                   ${CMAKE_CURRENT_SOURCE_DIR}/ensemble/openmpi_leaks.supp)
  # Open MPI refuses to run as root unless told (containers, CI).
  set_tests_properties(cli.ensemble_mpirun_matches_one_process PROPERTIES
                       ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1")
endif()
# The V&V question on the bouncing ball for 2 s: velocity Verlet and RK4 are exact under gravity
# with impacts at their time (error below 1e-9 m against the oracle, far below the input spread);
# symplectic Euler is first order (measured 0.05 m off, the order of g dt t / 2 = 0.16 m), still
# below the spread of the ball's height that 10% on its 10 m start causes (measured 0.32 m).
add_test(NAME cli.ensemble_compares_numerical_error_with_input_spread
         COMMAND sh -c "rm -rf ens_cmp && \"$0\" ensemble \"$1\"/scenes/bouncing_ball.json --duration 2 --samples 64 --compare-numerical-error --out ens_cmp > /dev/null && python3 -c \"import csv,sys; rows={r['integrator']: r for r in csv.DictReader(open('ens_cmp/numerical_error_vs_spread.csv'))}; e=lambda i: float(rows[i]['numerical_error']); s=lambda i: float(rows[i]['input_spread']); assert e('velocity_verlet') < 1e-9 and e('rk4') < 1e-9, rows; assert 0.02 < e('symplectic_euler') < 0.5, rows; assert all(0.1 < s(i) < 2 and rows[i]['error_below_spread'] == ('yes' if e(i) < s(i) else 'no') for i in rows), rows; assert rows['velocity_verlet']['reference'].startswith('oracle'), rows\""
                 ${GP_BIN} ${CMAKE_SOURCE_DIR})
