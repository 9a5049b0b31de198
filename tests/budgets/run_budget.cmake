# Runs one frame-budget case: renders it with --stats, then fails when any count of the stats'
# `work` map (render::WorkCounters: light evaluations by class, shadow taps, froxel pairs, SSR
# steps, AO samples, ...) exceeds the budget committed beside the case, or when a budgeted
# count is missing from the stats. Counts are deterministic where times are not, so a pass that
# starts doing 10x the work fails here whatever the machine's load.
#
#   cmake -DENGINE=<executable> -DBUDGET=<tests/budgets/NAME.json> -DOUT=<dir> -P run_budget.cmake
#
# NAME.json: {"args": [...], "work": {"<count>": <most allowed>, ...}}. Raise a budget only in
# a commit that says why the frame now needs the work.
cmake_minimum_required(VERSION 3.25)
file(READ "${BUDGET}" budget)
get_filename_component(name "${BUDGET}" NAME_WE)
string(JSON argCount LENGTH "${budget}" args)
set(args)
math(EXPR last "${argCount} - 1")
foreach(i RANGE ${last})
  string(JSON arg GET "${budget}" args ${i})
  string(REPLACE "@SOURCE_DIR@" "${SOURCE_DIR}" arg "${arg}")
  list(APPEND args "${arg}")
endforeach()
file(MAKE_DIRECTORY "${OUT}")
set(stats "${OUT}/${name}.stats.json")
file(REMOVE "${stats}")
execute_process(COMMAND "${ENGINE}" ${args} --stats "${stats}"
                WORKING_DIRECTORY "${SOURCE_DIR}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0 OR NOT EXISTS "${stats}")
  message(FATAL_ERROR "budget ${name}: ${ENGINE} ${args} failed (${result}):\n${output}")
endif()
file(READ "${stats}" measured)

string(JSON countNames LENGTH "${budget}" work)
math(EXPR last "${countNames} - 1")
set(over)
foreach(i RANGE ${last})
  string(JSON count MEMBER "${budget}" work ${i})
  string(JSON allowed GET "${budget}" work ${count})
  string(JSON value ERROR_VARIABLE missing GET "${measured}" work ${count})
  if(missing)
    list(APPEND over "${count}: not in the stats' work map")
  elseif(value GREATER allowed)
    list(APPEND over "${count}: ${value} > budget ${allowed}")
  else()
    message(STATUS "${name} ${count}: ${value} <= ${allowed}")
  endif()
endforeach()
if(over)
  list(JOIN over "\n  " lines)
  message(FATAL_ERROR "budget ${name} (${BUDGET}) exceeded:\n  ${lines}\n"
                      "Find what the frame now does more of; raise the budget only in a commit "
                      "that says why.")
endif()
