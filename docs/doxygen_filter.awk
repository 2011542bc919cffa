# Doxygen input filter for the public headers (docs/Doxyfile): their comments are plain `//`
# comments, which Doxygen does not read. The comment that opens a file becomes the file's
# description, a comment on lines of its own documents what follows it, and a comment after code
# on the same line documents that member. Code is passed through unchanged.
BEGIN { in_header = 1 }
in_header && /^\/\// { sub(/^\/\//, "///"); if (!opened) { print "/// @file"; opened = 1 } print; next }
{ in_header = 0 }
/^[ \t]*\/\// { sub(/\/\//, "///"); print; next }
/[;{,][ \t]*\/\/ / { sub(/[ \t]*\/\/ /, " ///< "); print; next }
{ print }
