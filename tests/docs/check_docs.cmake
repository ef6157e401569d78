# The documentation's own checks (ctest: docs.index, labels docs and unit):
#
#   cmake -DSOURCE_DIR=<exidel source tree> -P check_docs.cmake
#
# Fails, naming the file, when
#   - a file or directory directly in docs/ is not indexed in docs/README.md (a file
#     linked as "(name)" or named as "`name`", a directory named as "name/"; README.md
#     itself is the index);
#   - a file linked from README.md or docs/README.md does not exist (relative links
#     outside fenced code blocks; web and mail links and pure #anchors are not checked,
#     and an anchor after a file name is dropped before the check);
#   - README.md has more than 350 lines;
#   - a line of README.md reads as a work log: issue numbers, "session", "goal met",
#     "goal missed", "before/after" (any case). History belongs in CHANGELOG.md.
cmake_minimum_required(VERSION 3.25)

if(NOT DEFINED SOURCE_DIR)
  message(FATAL_ERROR "check_docs.cmake: run as cmake -DSOURCE_DIR=<exidel source tree> -P check_docs.cmake")
endif()
set(readme ${SOURCE_DIR}/README.md)
set(docs_dir ${SOURCE_DIR}/docs)
set(docs_index ${docs_dir}/README.md)
set(max_readme_lines 350)
set(history_regex "(issue [0-9]+|session|goal (met|missed)|before/after)")
set(problems "")

foreach(required IN ITEMS ${readme} ${docs_index})
  if(NOT EXISTS ${required})
    message(FATAL_ERROR "check_docs.cmake: ${required} does not exist")
  endif()
endforeach()

# markdown_lines(<file> <out_var>): the file's lines as a CMake list. Semicolons and
# square brackets would split or group list elements, so they travel as placeholders;
# unescape_line() puts them back.
function(markdown_lines file out_var)
  file(READ ${file} text)
  string(REPLACE ";" "@SEMICOLON@" text "${text}")
  string(REPLACE "[" "@LBRACKET@" text "${text}")
  string(REPLACE "]" "@RBRACKET@" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()
function(unescape_line line out_var)
  string(REPLACE "@SEMICOLON@" ";" line "${line}")
  string(REPLACE "@LBRACKET@" "[" line "${line}")
  string(REPLACE "@RBRACKET@" "]" line "${line}")
  set(${out_var} "${line}" PARENT_SCOPE)
endfunction()

# check_links(<markdown file>): every relative link target outside fenced code blocks
# must exist, relative to the file's directory.
function(check_links file)
  get_filename_component(dir ${file} DIRECTORY)
  file(RELATIVE_PATH shown ${SOURCE_DIR} ${file})
  markdown_lines(${file} lines)
  set(in_fence FALSE)
  set(number 0)
  set(found "")
  foreach(escaped IN LISTS lines)
    math(EXPR number "${number} + 1")
    unescape_line("${escaped}" line)
    if(line MATCHES "^[ \t]*```")
      if(in_fence)
        set(in_fence FALSE)
      else()
        set(in_fence TRUE)
      endif()
      continue()
    endif()
    if(in_fence)
      continue()
    endif()
    # Matched on the escaped line: a list element holding "]" would not split.
    string(REGEX MATCHALL "@RBRACKET@\\([^)]+\\)" links "${escaped}")
    foreach(link IN LISTS links)
      string(REGEX REPLACE "^@RBRACKET@\\((.*)\\)$" "\\1" target "${link}")
      unescape_line("${target}" target)
      string(STRIP "${target}" target)
      string(REGEX REPLACE "^<(.*)>$" "\\1" target "${target}")
      # A title after the target: [text](file "title").
      string(REGEX REPLACE "[ \t]+\".*\"$" "" target "${target}")
      if(target MATCHES "^(https?|mailto|ftp):" OR target MATCHES "^#")
        continue()
      endif()
      string(REGEX REPLACE "#.*$" "" path "${target}")
      if(path STREQUAL "")
        continue()
      endif()
      if(NOT EXISTS "${dir}/${path}")
        string(REPLACE ";" "@SEMICOLON@" target "${target}")
        list(APPEND found "${shown}:${number}: the link target '${target}' does not exist")
      endif()
    endforeach()
  endforeach()
  set(problems "${problems};${found}" PARENT_SCOPE)
endfunction()

# 1. Every file and directory directly in docs/ is indexed in docs/README.md.
file(READ ${docs_index} index_text)
file(GLOB entries RELATIVE ${docs_dir} LIST_DIRECTORIES true ${docs_dir}/*)
foreach(entry IN LISTS entries)
  if(entry STREQUAL "README.md")
    continue()
  endif()
  string(FIND "${index_text}" "(${entry})" as_link)
  string(FIND "${index_text}" "`${entry}`" as_name)
  string(FIND "${index_text}" "${entry}/" as_directory)
  if(IS_DIRECTORY ${docs_dir}/${entry})
    if(as_directory EQUAL -1)
      list(APPEND problems "docs/${entry}/ is not indexed in docs/README.md (name it as ${entry}/)")
    endif()
  elseif(as_link EQUAL -1 AND as_name EQUAL -1)
    list(APPEND problems "docs/${entry} is not indexed in docs/README.md (add a line [${entry}](${entry}): what it is)")
  endif()
endforeach()

# 2. Every link of README.md and docs/README.md resolves.
check_links(${readme})
check_links(${docs_index})

# 3. README.md has at most 350 lines.
file(READ ${readme} readme_text)
string(REGEX MATCHALL "\n" newlines "${readme_text}")
list(LENGTH newlines line_count)
if(NOT readme_text MATCHES "\n$" AND NOT readme_text STREQUAL "")
  math(EXPR line_count "${line_count} + 1")
endif()
if(line_count GREATER max_readme_lines)
  list(APPEND problems "README.md has ${line_count} lines, more than ${max_readme_lines}: move detail to docs/ (docs/README.md indexes the pages)")
endif()

# 4. No work-log wording in README.md.
markdown_lines(${readme} readme_lines)
set(number 0)
foreach(escaped IN LISTS readme_lines)
  math(EXPR number "${number} + 1")
  unescape_line("${escaped}" line)
  string(TOLOWER "${line}" lower)
  if(lower MATCHES "${history_regex}")
    list(APPEND problems "README.md:${number}: '${CMAKE_MATCH_1}' reads as history (it belongs in CHANGELOG.md): ${escaped}")
  endif()
endforeach()

list(REMOVE_ITEM problems "")
if(problems)
  list(LENGTH problems count)
  list(JOIN problems "\n  " text)
  unescape_line("${text}" text)  # the lines quoted in the messages, as they are written
  message(FATAL_ERROR "docs check: ${count} problem(s):\n  ${text}")
endif()
message(STATUS "docs check: every file in docs/ indexed, every link of README.md and docs/README.md resolves, README.md has ${line_count} lines and no work-log wording")
