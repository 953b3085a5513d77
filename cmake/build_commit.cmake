# Writes OUT, a C++ file defining wheelwear::cli::build_commit(): the git commit of SOURCE
# ("unknown" outside a git checkout; "-modified" with uncommitted changes to tracked files).
# Run at every build; the file is rewritten only when the commit changes, so that only the
# command-line program is relinked.
execute_process(COMMAND git -C "${SOURCE}" rev-parse --short=12 HEAD
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE failed ERROR_QUIET)
if(failed OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git -C "${SOURCE}" status --porcelain --untracked-files=no
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT changes STREQUAL "")
    string(APPEND commit "-modified")
  endif()
endif()
set(text "// Written at build time by cmake/build_commit.cmake.\n#include \"build_commit.hpp\"\n\nnamespace wheelwear::cli {\n\nconst char* build_commit() { return \"${commit}\"; }\n\n}  // namespace wheelwear::cli\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
