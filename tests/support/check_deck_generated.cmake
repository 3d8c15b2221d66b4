# A deck names its lesson's passes and exercises only through the generated blocks: a line that is
# exactly {{passes}} and one that is exactly {{exercises}}.
# Run: cmake -DDECK=slides/NN_name.md -P this
file(STRINGS ${DECK} passes REGEX "^{{passes}}[ \t]*$")
file(STRINGS ${DECK} exercises REGEX "^{{exercises}}[ \t]*$")
if(NOT passes OR NOT exercises)
  message(FATAL_ERROR "${DECK}: needs a line {{passes}} and a line {{exercises}} (generated from the lesson; "
                      "found passes '${passes}', exercises '${exercises}')")
endif()
