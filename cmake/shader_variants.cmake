# shader_variants.cmake — the "// hfs-variant: NAME VALUE, NAME2 VALUE" lines
# of a shader, shared by every build-time shader check (embed_shaders.cmake,
# runtime/gles/CMakeLists.txt) so they all compile the same variants.
#
# hfs_shader_variants(<text> <out_labels> <out_defines>): two parallel lists,
# one entry without defines ("<none>", "") and then one per variant line;
# each defines entry is the "#define ..." block (newline-separated) that the
# runtime would put after "#version 300 es".

function(hfs_shader_variants text out_labels out_defines)
  set(labels "<none>")
  set(blocks "")
  list(APPEND blocks " ") # placeholder for the empty block (lists drop "")
  string(REGEX MATCHALL "//[ \t]*hfs-variant:[^\n]*" lines "${text}")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^//[ \t]*hfs-variant:[ \t]*" "" line "${line}")
    string(REPLACE ";" "," line "${line}") # keep it one list element
    list(APPEND labels "${line}")
    string(REPLACE "," ";" defs "${line}")
    set(block "")
    foreach(def IN LISTS defs)
      string(STRIP "${def}" def)
      if(def)
        string(APPEND block "#define ${def}\n")
      endif()
    endforeach()
    list(APPEND blocks "${block}")
  endforeach()
  set(${out_labels} "${labels}" PARENT_SCOPE)
  set(${out_defines} "${blocks}" PARENT_SCOPE)
endfunction()
