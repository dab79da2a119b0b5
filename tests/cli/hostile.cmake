# Hostile input to the `soma` command line (issue 24; papers/robustness.md is the table of these
# cases): no crash, no hang, no silent wrong answer. Each case is a CTest test `cli: hostile CASE`,
# run by expect.cmake: the exit code (2 for bad input, docs/cli.md) and a regex on the message.
# Inputs are in tests/cli/hostile/; the ones too large to keep in the repository are written at
# configure time into the build tree.
set(SOMA_HOSTILE_DIR ${CMAKE_CURRENT_LIST_DIR}/hostile)
set(SOMA_HOSTILE_OUT ${CMAKE_CURRENT_BINARY_DIR}/hostile)
file(MAKE_DIRECTORY ${SOMA_HOSTILE_OUT})

# soma_hostile_test(CASE RC MATCH [NOMATCH regex] [STDOUT file] [TIMEOUT s] ARGS soma-arguments...)
# RUN replaces `soma` as the program (then ARGS are the whole command line).
function(soma_hostile_test case rc match)
  cmake_parse_arguments(H "" "NOMATCH;STDOUT;TIMEOUT;RUN" "ARGS" ${ARGN})
  if(H_RUN)
    set(cmd "${H_RUN};${H_ARGS}")
  else()
    set(cmd "$<TARGET_FILE:soma>;${H_ARGS}")
  endif()
  add_test(NAME "cli: hostile ${case}"
           COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" -DRC=${rc} "-DMATCH=${match}" "-DNOMATCH=${H_NOMATCH}"
                   "-DSTDOUT=${H_STDOUT}" "-DNAME=hostile ${case}" -P ${CMAKE_CURRENT_LIST_DIR}/expect.cmake)
  if(H_TIMEOUT)
    set_tests_properties("cli: hostile ${case}" PROPERTIES TIMEOUT ${H_TIMEOUT})
  endif()
endfunction()

set(H ${SOMA_HOSTILE_DIR})
set(R ${CMAKE_SOURCE_DIR}/studies/robots)
set(U ${CMAKE_SOURCE_DIR}/tests/io/urdf)

# ---- limits before a recursive parser sees the input (io/include/soma/io/input_limits.hpp) ------
string(REPEAT "[" 100000 open)
string(REPEAT "]" 100000 close)
file(WRITE ${SOMA_HOSTILE_OUT}/robot_deep_base.json
     "{\"convention\": \"dh\", \"joints\": [{\"type\": \"R\", \"a\": 0, \"alpha\": 0, \"d\": 0, \"theta\": 0}], \"base\": ${open}${close}}\n")
soma_hostile_test("robot base nested 100000 deep" 2 "robot_deep_base.json.*nest.*64" TIMEOUT 30
                  ARGS fk ${SOMA_HOSTILE_OUT}/robot_deep_base.json --joints 0)
string(REPEAT "<visual>" 100000 open)
string(REPEAT "</visual>" 100000 close)
file(WRITE ${SOMA_HOSTILE_OUT}/urdf_deep.urdf "<robot name=\"deep\"><link name=\"a\">${open}${close}</link></robot>\n")
soma_hostile_test("URDF elements nested 100000 deep" 2 "urdf_deep.urdf.*64" TIMEOUT 30
                  ARGS fk ${SOMA_HOSTILE_OUT}/urdf_deep.urdf --joints 0)
set(chain "<robot name=\"chain\">\n<link name=\"l0\"/>\n")
foreach(i RANGE 1 1001)
  math(EXPR p "${i} - 1")
  string(APPEND chain "<link name=\"l${i}\"/><joint name=\"j${i}\" type=\"revolute\"><parent link=\"l${p}\"/><child link=\"l${i}\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n")
endforeach()
string(APPEND chain "</robot>\n")
file(WRITE ${SOMA_HOSTILE_OUT}/urdf_chain_1001.urdf "${chain}")
soma_hostile_test("URDF chain of 1001 joints" 2 "urdf_chain_1001.urdf.*1000 joints" TIMEOUT 30
                  ARGS fk ${SOMA_HOSTILE_OUT}/urdf_chain_1001.urdf --joints 0)
soma_hostile_test("URDF with a cycle" 2 "cycle.urdf.*cycle" TIMEOUT 30 ARGS fk ${U}/cycle.urdf --joints 0)
soma_hostile_test("URDF with a self loop" 2 "self_loop.urdf.*its own parent" TIMEOUT 30 ARGS fk ${U}/self_loop.urdf --joints 0)
soma_hostile_test("input from /dev/zero" 2 "/dev/zero: the pose file is larger than 16 MiB" TIMEOUT 30 ARGS pose /dev/zero)

# ---- one number reader for every file and flag (io/include/soma/io/number.hpp) -------------------
soma_hostile_test("hex in a robot file (double)" 2 "robot_hex.json: joints\\[1\\]\\.a: \"0x10\" is not a decimal number \\(hexadecimal\\)"
                  ARGS fk ${H}/robot_hex.json --joints 0,0,0,0,0,0)
soma_hostile_test("hex in a robot file (mpfr)" 2 "robot_hex.json: joints\\[1\\]\\.a: \"0x10\" is not a decimal number \\(hexadecimal\\)"
                  ARGS fk ${H}/robot_hex.json --joints 0,0,0,0,0,0 --scalar mpfr)
soma_hostile_test("hex in a pose file" 2 "pose_hex.json: translation\\[0\\]: \"0x10\" is not a decimal number \\(hexadecimal\\)"
                  ARGS pose ${H}/pose_hex.json)
soma_hostile_test("hex in a platform file" 2 "platform_hex.json: leg_lengths\\[2\\]: \"0x10\" is not a decimal number \\(hexadecimal\\)"
                  ARGS stewart ${H}/platform_hex.json)
soma_hostile_test("hex in --joints" 2 "--joints value 2: \"0x10\" is not a decimal number \\(hexadecimal\\)" ARGS fk ${R}/general6r.json --joints 0,0x10,0,0,0,0)
soma_hostile_test("trailing comma in --joints" 2 "--joints value 7: empty \\(a trailing comma\\?\\)" ARGS fk ${R}/general6r.json --joints 0,0,0,0,0,0,)
soma_hostile_test("JSON number 1e400" 2 "robot_1e400.json: joints\\[1\\]\\.a: 1e400 is outside the range of a JSON number"
                  ARGS fk ${H}/robot_1e400.json --joints 0,0,0,0,0,0)
soma_hostile_test("1e-50 in float" 2 "robot_tiny.json: joints\\[2\\]\\.d: 1e-50 is too small for float"
                  ARGS fk ${H}/robot_tiny.json --joints 0,0,0,0,0,0 --scalar float)
soma_hostile_test("\"1e-320\" in double" 2 "robot_subnormal.json: joints\\[2\\]\\.d: \"1e-320\" is too small for double \\(a subnormal double keeps 11 of its 53 bits"
                  ARGS fk ${H}/robot_subnormal.json --joints 0,0,0,0,0,0)
soma_hostile_test("\"1e-320\" in long double" 0 "rank 6"
                  ARGS fk ${H}/robot_subnormal.json --joints 0.1,0.2,0.3,0.4,0.5,0.6 --scalar long-double)
soma_hostile_test("duplicate JSON key" 2 "robot_duplicate_key.json: joints\\[1\\]\\.a: the key \"a\" is given twice"
                  ARGS fk ${H}/robot_duplicate_key.json --joints 0,0,0,0,0,0)
soma_hostile_test("unknown key in a planar scene" 2 "planar_unknown_key.json.*colour" ARGS planar ${H}/planar_unknown_key.json)
soma_hostile_test("mode 4294967297 in a planar scene" 2 "planar_mode_wraps.json.*must be 1 or -1 \\(assembly mode\\), got 4294967297"
                  ARGS planar ${H}/planar_mode_wraps.json)
soma_hostile_test("scene bits out of range" 2 "outputs\\.solve\\.bits: \"3\" is outside 16 … 8192"
                  ARGS scene ${CMAKE_SOURCE_DIR}/tests/io/scenes/bad_bits.json)
# Flags: read as text by the same reader, in their ranges, before anything runs.
if(SOMA_CLI_STUDIES)  # these run studies (not in a soma built without them)
soma_hostile_test("--bits 100000" 2 "--bits: \"100000\" is outside 16 … 8192" TIMEOUT 10
                  ARGS study run GF-2.1-U1-unit-complex --scalar mpfr --bits 100000 --no-figures)
endif()
soma_hostile_test("--bits 0x10" 2 "--bits: \"0x10\" is not a decimal number \\(hexadecimal\\)" TIMEOUT 10
                  ARGS pose ${R}/puma560_pose.json --scalar mpfr --bits 0x10)
soma_hostile_test("--bits 2.5" 2 "--bits: \"2.5\" is not an integer" TIMEOUT 10 ARGS pose ${R}/puma560_pose.json --bits 2.5)
soma_hostile_test("--bits 1e3 is 1000" 0 "1000 significant bits" TIMEOUT 30
                  ARGS pose ${R}/puma560_pose.json --scalar mpfr --bits 1e3)
soma_hostile_test("workspace --grid 1000000" 2 "--grid: \"1000000\" is outside 8 … 2048" TIMEOUT 10
                  ARGS workspace ${R}/arm3r.json --grid 1000000)
soma_hostile_test("workspace --samples 1e400" 2 "--samples: \"1e400\" is outside 1 … 10000000" TIMEOUT 10
                  ARGS workspace ${R}/arm3r.json --samples 1e400)
soma_hostile_test("workspace --seconds inf" 2 "--seconds: \"inf\" is not a decimal number \\(NaN and infinity" TIMEOUT 10
                  ARGS workspace ${R}/arm3r.json --seconds inf)
soma_hostile_test("workspace --margin 1e400" 2 "--margin: \"1e400\" is outside the range of double" TIMEOUT 10
                  ARGS workspace ${R}/arm3r.json --margin 1e400)
soma_hostile_test("workspace --seconds 1e-50" 2 "--seconds: \"1e-50\" is outside 0.001 … 3600" TIMEOUT 10
                  ARGS workspace ${R}/arm3r.json --from 0,0,0 --to 1,1,1 --seconds 1e-50)
soma_hostile_test("cuspidal --poses 0x4" 2 "--poses: \"0x4\" is not a decimal number \\(hexadecimal\\)" TIMEOUT 10
                  ARGS cuspidal ${R}/cusp6r_orthogonal_wrist.json --poses 0x4)
soma_hostile_test("cuspidal --threads 4294967297" 2 "--threads: \"4294967297\" is outside 0 … 1024" TIMEOUT 10
                  ARGS cuspidal ${R}/cusp3r_orthogonal_wenger.json --map a2:0.5:4:3,a3:0.2:3:3 --threads 4294967297)
soma_hostile_test("cuspidal --map with a hex bound" 2 "MAX '0x10' is not a finite number" TIMEOUT 10
                  ARGS cuspidal ${R}/cusp3r_orthogonal_wenger.json --map a2:0.5:0x10:3,a3:0.2:3:3)
soma_hostile_test("cuspidal --pair-seconds -1" 2 "--pair-seconds: \"-1\" is outside 0.001 … 3600" TIMEOUT 10
                  ARGS cuspidal ${R}/cusp6r_orthogonal_wrist.json --pair-seconds=-1)

# ---- answers that were wrong in silence ----------------------------------------------------------
foreach(e 3 6 9 12)
  soma_hostile_test("pose rotated by 1e-${e} passes its screw round trip" 0 "screw [0-9.e-]+ .*PASS"
                    ARGS pose ${H}/pose_angle_1e-${e}.json)
  foreach(scalar long-double mpfr)
    soma_hostile_test("pose rotated by 1e-${e} passes in ${scalar}" 0 "screw [0-9.e-]+ .*PASS"
                      ARGS pose ${H}/pose_angle_1e-${e}.json --scalar ${scalar})
  endforeach()
endforeach()
soma_hostile_test("link lengths 1e160: rank 6" 0 "\"rank\": 6" ARGS fk ${H}/robot_huge.json --joints 0.1,0.2,0.3,0.4,0.5,0.6 --json)
soma_hostile_test("platform x1e200: the general platform's postures" 0 "complex solutions: 40 found, 40 expected .*real postures: 8 "
                  ARGS stewart ${H}/platform_huge.json)
soma_hostile_test("exact singularity: condition \"inf\"" 0 "\"condition\": \"inf\".*\"rank\": 1"
                  ARGS fk ${H}/robot_singular.json --joints 0,0 --json)

# ---- output ------------------------------------------------------------------------------------
if(SOMA_CLI_STUDIES)  # these run studies (not in a soma built without them)
soma_hostile_test("stdout to /dev/full" 2 "soma: cannot write to standard output"
                  STDOUT /dev/full ARGS study list)
endif()
soma_hostile_test("--json to /dev/full" 2 "cannot write to standard output" STDOUT /dev/full
                  ARGS pose ${R}/puma560_pose.json --json)
# --out below a regular file cannot be created (as root, a read-only mode bit would not stop us).
if(SOMA_CLI_STUDIES)  # these run studies (not in a soma built without them)
soma_hostile_test("study run --out unwritable" 2 "--out .*expect.cmake/out: cannot create the folder" TIMEOUT 30
                  NOMATCH "PASS|FAIL" ARGS study run GF-13-figures --out ${CMAKE_CURRENT_LIST_DIR}/expect.cmake/out)
soma_hostile_test("report --out unwritable" 2 "--out .*expect.cmake/out: cannot create the folder" TIMEOUT 30
                  NOMATCH "PASS|FAIL" ARGS report --only GF-2.1-U1-unit-complex --out ${CMAKE_CURRENT_LIST_DIR}/expect.cmake/out)
endif()
soma_hostile_test("--json with a file name that is not UTF-8" 0 "\"input\": \"[^\"]*pose_�\\.json\""
                  RUN sh ARGS ${H}/non_utf8_name.sh $<TARGET_FILE:soma> ${R}/puma560_pose.json ${SOMA_HOSTILE_OUT})
