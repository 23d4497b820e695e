# shader_variants.cmake — the "// hfs-variant: NAME VALUE, NAME2 VALUE" lines
# of a shader, shared by every build-time shader check (embed_shaders.cmake,
# runtime/gles/CMakeLists.txt) so they all compile the same variants.
#
# hfs_shader_variants(<text> <out_labels> <out_prefixes>): two parallel
# lists, one entry without defines ("<none>") and then one per variant line;
# each prefix is what the runtime puts before the shader's text: the
# "#version 300 es" line and the variant's "#define ..." lines.
# "// hfs-base: NAME VALUE, ..." lines are defines every program of the
# shader is built with (its C side always sets them, e.g. horizons.frag's
# HFS_CELLS): they go into every entry, the "<none>" one included.

function(hfs_shader_variants text out_labels out_prefixes)
  set(base "")
  string(REGEX MATCHALL "//[ \t]*hfs-base:[^\n]*" base_lines "${text}")
  foreach(line IN LISTS base_lines)
    string(REGEX REPLACE "^//[ \t]*hfs-base:[ \t]*" "" line "${line}")
    string(REPLACE ";" "," line "${line}")
    string(REPLACE "," ";" defs "${line}")
    foreach(def IN LISTS defs)
      string(STRIP "${def}" def)
      if(def)
        string(APPEND base "#define ${def}\n")
      endif()
    endforeach()
  endforeach()
  set(labels "<none>")
  set(prefixes "#version 300 es\n${base}")
  string(REGEX MATCHALL "//[ \t]*hfs-variant:[^\n]*" lines "${text}")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^//[ \t]*hfs-variant:[ \t]*" "" line "${line}")
    string(REPLACE ";" "," line "${line}") # keep it one list element
    list(APPEND labels "${line}")
    string(REPLACE "," ";" defs "${line}")
    set(prefix "#version 300 es\n${base}")
    foreach(def IN LISTS defs)
      string(STRIP "${def}" def)
      if(def)
        string(APPEND prefix "#define ${def}\n")
      endif()
    endforeach()
    list(APPEND prefixes "${prefix}")
  endforeach()
  set(${out_labels} "${labels}" PARENT_SCOPE)
  set(${out_prefixes} "${prefixes}" PARENT_SCOPE)
endfunction()
