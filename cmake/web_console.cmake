# The console's files (web/), embedded into one generated source by cmake/embed_web.cmake, for
# the program and for the web request fuzzer alike: editing a file under web/ rebuilds it.
# Every module under web/js/, every page fragment under web/pages/ and style sheet under web/css/
# (the pages the console loads when first opened, navigation.js) is served: a new one needs no
# edit here (CONFIGURE_DEPENDS re-globs at the next build).
file(GLOB AZT_WEB_MODULES RELATIVE ${PROJECT_SOURCE_DIR}/web CONFIGURE_DEPENDS
     ${PROJECT_SOURCE_DIR}/web/js/*.js ${PROJECT_SOURCE_DIR}/web/pages/*.html
     ${PROJECT_SOURCE_DIR}/web/css/*.css)
list(SORT AZT_WEB_MODULES)
# index.html is the console (/), panel.html the 480×320 touch panel (/panel, docs/panel.md).
set(AZT_WEB_FILES index.html app.css panel.html panel.css ${AZT_WEB_MODULES})

# Defines the custom command that writes OUT_CPP (a web_assets.cpp holding AZT_WEB_FILES).
function(azt_embed_web_console out_cpp)
  list(TRANSFORM AZT_WEB_FILES PREPEND ${PROJECT_SOURCE_DIR}/web/ OUTPUT_VARIABLE paths)
  list(JOIN AZT_WEB_FILES "," file_list)
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DSRC_DIR=${PROJECT_SOURCE_DIR}/web -DFILES=${file_list}
            -DOUT=${out_cpp} -P ${PROJECT_SOURCE_DIR}/cmake/embed_web.cmake
    DEPENDS ${paths} ${PROJECT_SOURCE_DIR}/cmake/embed_web.cmake
    COMMENT "Embedding the web console")
endfunction()
