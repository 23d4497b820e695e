# shader_variants.cmake — the "// hfs-variant: NAME VALUE, NAME2 VALUE" lines
# of a shader, shared by every build-time shader check (embed_shaders.cmake,
# runtime/gles/CMakeLists.txt) so they all compile the same variants.
#
# hfs_shader_variants(<text> <out_labels> <out_prefixes>): two parallel
# lists, one entry without defines ("<none>") and then one per variant line;
# each prefix is what the runtime puts before the shader's text: the
# "#version 300 es" line and the variant's "#define ..." lines.

function(hfs_shader_variants text out_labels out_prefixes)
  set(labels "<none>")
  set(prefixes "#version 300 es\n")
  string(REGEX MATCHALL "//[ \t]*hfs-variant:[^\n]*" lines "${text}")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^//[ \t]*hfs-variant:[ \t]*" "" line "${line}")
    string(REPLACE ";" "," line "${line}") # keep it one list element
    list(APPEND labels "${line}")
    string(REPLACE "," ";" defs "${line}")
    set(prefix "#version 300 es\n")
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
