# the documentation site (docs/, Sphinx with MyST Markdown and the Read the
# Docs theme; packages in docs/dependencies.md):
#   cmake --build build --target docs   ->  build/docs/html/index.html
# -W --keep-going: every warning (a broken cross-reference, a page outside
# the table of contents, a missing anchor) fails the build after all are
# listed; -n: nitpicky, every reference must resolve.
find_program(MJB_SPHINX_BUILD sphinx-build)
set(MJB_SPHINX_FLAGS -W --keep-going -n -q)
if(MJB_SPHINX_BUILD)
  add_custom_target(docs
    COMMAND ${MJB_SPHINX_BUILD} ${MJB_SPHINX_FLAGS} -b html ${PROJECT_SOURCE_DIR}/docs
      ${PROJECT_BINARY_DIR}/docs/html
    COMMENT "docs: Sphinx site in ${PROJECT_BINARY_DIR}/docs/html"
    VERBATIM)
else()
  add_custom_target(docs
    COMMAND ${CMAKE_COMMAND} -E echo
      "docs: sphinx-build not found: install python3-sphinx python3-sphinx-rtd-theme python3-myst-parser (scripts/setup.sh)"
    COMMAND ${CMAKE_COMMAND} -E false
    VERBATIM)
endif()
