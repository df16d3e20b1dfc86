# `grape sample` as a user runs it: the JSON it prints for a small timeline scene whose
# positions follow by hand, and its errors (exit status 2, the reason on stderr, nothing on
# stdout). Each case prints what it saw and fails (a CMake error) when it is not as expected.
# No shell: a cross build runs the tool through its emulator (Wine).
#   cmake -DCASE=case -DGRAPE=exe [-DEMULATOR=a|b] -DWORK=folder -DSCENES=folder -P tests/tool_sample.cmake
string(REPLACE "|" ";" emulator "${EMULATOR}")
set(work "${WORK}/${CASE}")
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}")

function(fail why)
  message(FATAL_ERROR "FAIL: ${why}")
endfunction()

# run(ARGS...): the tool's exit status, stdout and stderr in status, out and err.
macro(run)
  execute_process(COMMAND ${emulator} ${GRAPE} ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("status ${status}; stdout:\n${out}stderr:\n${err}")
endmacro()

# expect_error(TEXT): status 2, TEXT (a fixed string) on stderr, stdout empty.
function(expect_error text)
  if(NOT status STREQUAL "2")
    fail("exit status ${status}, expected 2")
  endif()
  string(FIND "${err}" "${text}" at)
  if(at EQUAL -1)
    fail("stderr does not say '${text}'")
  endif()
  if(NOT out STREQUAL "")
    fail("printed something on stdout")
  endif()
endfunction()

function(expect_status_0)
  if(NOT status STREQUAL "0")
    fail("exit status ${status}")
  endif()
endfunction()

function(expect_output expected why)
  if(NOT out STREQUAL expected)
    fail("${why}; expected:\n${expected}")
  endif()
endfunction()

# Timeline t: delay 1, a (1 s along x to 100) at 0, b (1 s along y to 10) at a's start + 1,
# so one play lasts 2 s; it plays twice with 0.5 s between, the second time backwards (scene
# times 3.5 to 5.5). c runs free: 4 s from (0, 0) to (1, 1). Every time below is a sum of
# powers of two, so the positions are exact. By hand, at scene time
#   0     t waits:                      a, b at their starts; c at 0
#   1.25  t at 0.25:                    a at u = 0.25; b not started
#   2.5   t at 1.5:                     a ended; b 0.5 s in
#   3.25  t's repeat delay, held at 2:  a, b at their ends
#   3.75  t backwards 0.25 s in, at 1.75: a at its end; b 0.75 s in
#   4.75  t backwards 1.25 s in, at 0.75: a at u = 0.75; b back at its start
#   10    t ended at its start:         a, b at their starts; c at its end
set(scene [=[{"animations": [
  {"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "duration": 1},
  {"name": "b", "path": {"kind": "linear", "start": [0, 0], "end": [0, 10]}, "duration": 1},
  {"name": "c", "path": {"kind": "linear", "start": [0, 0], "end": [1, 1]}, "duration": 4},
  {"path": {"kind": "linear", "start": [0, 0], "end": [1, 1]}, "duration": 3}],
 "timelines": [{"name": "t", "delay": 1, "repeat": 1, "repeat_delay": 0.5, "yoyo": true,
                "children": [{"animation": "a"}, {"animation": "b", "at": "<+1"}]}]}
]=])
file(WRITE "${work}/scene.json" "${scene}")
set(scene_times 0,1.25,2.5,3.25,3.75,4.75,10)
set(scene_positions [=[[{"time": 0, "animations": {"a": [0, 0], "b": [0, 0], "c": [0, 0]}},
 {"time": 1.25, "animations": {"a": [25, 0], "b": [0, 0], "c": [0.3125, 0.3125]}},
 {"time": 2.5, "animations": {"a": [100, 0], "b": [0, 5], "c": [0.625, 0.625]}},
 {"time": 3.25, "animations": {"a": [100, 0], "b": [0, 10], "c": [0.8125, 0.8125]}},
 {"time": 3.75, "animations": {"a": [100, 0], "b": [0, 7.5], "c": [0.9375, 0.9375]}},
 {"time": 4.75, "animations": {"a": [75, 0], "b": [0, 0], "c": [1, 1]}},
 {"time": 10, "animations": {"a": [0, 0], "b": [0, 0], "c": [1, 1]}}]
]=])

# Properties by hand: x by 10 over 1 s, then by −4 over 0.5 s after it in a timeline (from
# where the first left it); a colour from black to white over 1 s; a vec2 from [0, 0] to
# [2, 4] over 2 s after a delay of 1 s; an angle from 350° to 10° the short way (to 370°).
# At 0: the initial values (v waiting); at 1.25: x 10 − 2, white, v 1/8 of the way, 370; at
# 2: x 6, v half way.
set(props [=[{"properties": [{"name": "x", "value": 0}, {"name": "c", "type": "color", "value": "#000000"},
            {"name": "v", "type": "vec2", "value": [0, 0]},
            {"name": "a", "type": "angle", "value": 350, "unit": "degrees"}],
 "tweens": [{"name": "up", "property": "x", "by": 10, "duration": 1},
        {"name": "back", "property": "x", "by": -4, "duration": 0.5},
        {"property": "c", "to": "#ffffff", "duration": 1},
        {"property": "v", "from": [0, 0], "to": [2, 4], "duration": 2, "delay": 1},
        {"property": "a", "to": 10, "duration": 1}],
 "timelines": [{"name": "t", "children": [{"tween": "up"}, {"tween": "back"}]}]}
]=])
file(WRITE "${work}/props.json" "${props}")

if(CASE STREQUAL "values")
  run(sample "${work}/scene.json" --at ${scene_times})
  expect_status_0()
  expect_output("${scene_positions}" "not the positions derived by hand")
elseif(CASE STREQUAL "digits")
  # A third of a 3 s linear animation: u = 1/3 printed with 17 significant digits.
  string(REPLACE [=["duration": 4}]=] [=["duration": 3}]=] third "${scene}")
  file(WRITE "${work}/third.json" "${third}")
  run(sample "${work}/third.json" --at 1)
  expect_status_0()
  string(FIND "\n${out}"
         "\n[{\"time\": 1, \"animations\": {\"a\": [0, 0], \"b\": [0, 0], \"c\": [0.33333333333333331, 0.33333333333333331]}}]\n" at)
  if(at EQUAL -1)
    fail("not 1/3 with 17 significant digits")
  endif()
elseif(CASE STREQUAL "round_trip")
  # 17 significant digits: every number printed is the %.17g text of the double it reads
  # back as (a shorter or longer form, such as %g's 6 digits, would differ). CMake has no
  # floating point: the host's awk prints them.
  run(sample "${SCENES}/timeline_cutscene.json" --at 0.1,1.7,3.3,4.4,6.05,9.99)
  expect_status_0()
  string(REGEX MATCHALL "[0-9.eE+-]+" tokens "${out}")
  set(numbers "")
  foreach(t IN LISTS tokens)
    if(t MATCHES "[0-9]")
      list(APPEND numbers "${t}")
    endif()
  endforeach()
  if(NOT numbers)
    fail("no numbers")
  endif()
  find_program(AWK NAMES awk mawk gawk)
  if(NOT AWK)
    fail("awk not found (it prints the doubles the numbers read as)")
  endif()
  execute_process(COMMAND ${AWK} [=[BEGIN { for (i = 1; i < ARGC; i++) printf "%.17g\n", ARGV[i] + 0 }]=] ${numbers}
                  OUTPUT_VARIABLE again RESULT_VARIABLE awk_status)
  if(NOT awk_status STREQUAL "0")
    fail("awk failed (${awk_status})")
  endif()
  string(REGEX REPLACE "\n$" "" again "${again}")
  string(REPLACE "\n" ";" again "${again}")
  foreach(n a IN ZIP_LISTS numbers again)
    if(NOT n STREQUAL a)
      fail("${n} is not 17 significant digits of the double it reads as (${a})")
    endif()
  endforeach()
  foreach(name slide drop spin pulse wave)
    # (marked first: a list element holding '[' would swallow the separators after it)
    string(REPLACE "\"${name}\": [" "<found>" marked "${out}")
    string(REGEX MATCHALL "<found>" found "${marked}")
    list(LENGTH found count)
    if(NOT count EQUAL 6)
      fail("${name} is not at every time")
    endif()
  endforeach()
elseif(CASE STREQUAL "properties")
  run(sample "${work}/props.json" --at 0,1.25,2)
  expect_status_0()
  expect_output([=[[{"time": 0, "animations": {}, "properties": {"x": 0, "c": [0, 0, 0, 1], "v": [0, 0], "a": 350}},
 {"time": 1.25, "animations": {}, "properties": {"x": 8, "c": [1, 1, 1, 1], "v": [0.25, 0.5], "a": 370}},
 {"time": 2, "animations": {}, "properties": {"x": 6, "c": [1, 1, 1, 1], "v": [1, 2], "a": 370}}]
]=] "not the values derived by hand")
elseif(CASE STREQUAL "bad_property")
  string(REPLACE [=["property": "c"]=] [=["property": "colour"]=] bad "${props}")
  file(WRITE "${work}/bad.json" "${bad}")
  run(sample "${work}/bad.json" --at 0)
  expect_error([=[bad.json: scene: /tweens/2/property: no property named "colour" in /properties]=])
elseif(CASE STREQUAL "bad_time")
  run(sample "${work}/scene.json" --at 0,soon)
  expect_error("sample: --at must be a finite number (got 'soon')")
elseif(CASE STREQUAL "unknown_label")
  string(REPLACE [=["<+1"]=] [=["later+1"]=] bad "${scene}")
  file(WRITE "${work}/bad.json" "${bad}")
  run(sample "${work}/bad.json" --at 0)
  expect_error("bad.json: scene: /timelines/0/children/1/at: ")
  string(FIND "${err}" "later" at)
  if(at EQUAL -1)
    fail("stderr does not name the label")
  endif()
elseif(CASE STREQUAL "duplicate_names")
  # The unnamed animation named like c: a JSON object cannot hold both.
  string(REPLACE "\n  {\"path\"" "\n  {\"name\": \"c\", \"path\"" dup "${scene}")
  file(WRITE "${work}/dup.json" "${dup}")
  run(sample "${work}/dup.json" --at 0)
  expect_error([=[/animations/2 and /animations/3 are both named "c"]=])
elseif(CASE STREQUAL "three_d")
  # 3-D animations by hand: p (4 s along x to 8) a position only, 2 at 1 s; q (4 s from
  # (8, 0, 0) back to the origin, delayed 1 s by timeline t) turned by its rotation-minimizing
  # frame with the model's +x forward and +z up: tangent −x, normal +z, so the model turns by
  # π about z, the quaternion (0, 0, 0, ±1) (w ≥ 0, so the sign is the z part's), with the
  # position 8 − 2·(t − 1). Every number is exact; zeros may print as -0.
  file(WRITE "${work}/three_d.json" [=[{"animations3": [
  {"name": "p", "path": {"kind": "line", "points": [[0, 0, 0], [8, 0, 0]]}, "duration": 4},
  {"name": "q", "path": {"kind": "line", "points": [[8, 0, 0], [0, 0, 0]]}, "duration": 4, "align": "frame",
   "axes": {"forward": "+x", "up": "+z"}}],
 "animations": [{"name": "flat", "path": {"kind": "linear", "start": [0, 0], "end": [4, 0]}, "duration": 4}],
 "timelines": [{"name": "t", "delay": 1, "children": [{"animation3": "q"}]}]}
]=])
  run(sample "${work}/three_d.json" --at 1,3)
  expect_status_0()
  set(z "-?0")
  set(pose "{\"position\": \\[[48], ${z}, ${z}\\], \"orientation\": \\[${z}, ${z}, ${z}, -?1\\]}")
  set(want "^\\[{\"time\": 1, \"animations\": {\"flat\": \\[1, 0\\], \"p\": \\[2, 0, 0\\], \"q\": ${pose}}},\n")
  string(APPEND want " {\"time\": 3, \"animations\": {\"flat\": \\[3, 0\\], \"p\": \\[6, 0, 0\\], \"q\": ${pose}}}\\]\n$")
  message("expected:\n${want}")
  if(NOT out MATCHES "${want}")
    fail("not the 3-D positions and orientations derived by hand")
  endif()
  string(FIND "${out}" [=["q": {"position": [8, ]=] first)
  string(FIND "${out}" [=["q": {"position": [4, ]=] second)
  if(first EQUAL -1 OR second EQUAL -1)
    fail("q is not at 8 after its delay and at 4 two seconds later")
  endif()
  # A 3-D animation named like a 2-D one: a JSON object cannot hold both.
  file(READ "${work}/three_d.json" text)
  string(REPLACE [=["name": "flat"]=] [=["name": "p"]=] text "${text}")
  file(WRITE "${work}/three_d_dup.json" "${text}")
  run(sample "${work}/three_d_dup.json" --at 0)
  expect_error([=[/animations/0 and /animations3/0 are both named "p"]=])
elseif(CASE STREQUAL "missing_file")
  run(sample "${work}/none.json" --at 0)
  expect_error("cannot read ${work}/none.json: no such file")
elseif(CASE STREQUAL "non_ascii")
  # File names beyond ASCII (UTF-8 on the command line, UTF-16 on Windows) name the same
  # file, and messages name it as it was given.
  file(WRITE "${work}/dé_ü.json" "${scene}")
  run(sample "${work}/dé_ü.json" --at ${scene_times})
  expect_status_0()
  expect_output("${scene_positions}" "not the positions derived by hand")
  string(REPLACE [=["<+1"]=] [=["later+1"]=] bad "${scene}")
  file(WRITE "${work}/mauvais_é.json" "${bad}")
  run(sample "${work}/mauvais_é.json" --at 0)
  expect_error("${work}/mauvais_é.json: scene: /timelines/0/children/1/at: ")
  run(sample "${work}/absent_ü.json" --at 0)
  expect_error("cannot read ${work}/absent_ü.json: no such file")
else()
  fail("unknown case ${CASE}")
endif()
message("ok: ${CASE}")
