# Writes OUTPUT: a C++ file defining pathcl::embedded_kernel_files(), every file of the
# kernel tree ROOT (kernels/) as a byte array named by its path relative to ROOT, so the
# binary needs no kernel files at run time. host/cl/kernel_source.cpp resolves their
# #include lines; the order here does not matter.
file(GLOB_RECURSE paths RELATIVE ${ROOT} ${ROOT}/*.cl ${ROOT}/*.h)
list(SORT paths)
set(body "#include \"cl/embedded_kernels.h\"\nnamespace pathcl {\nnamespace {\n")
set(table "")
set(index 0)
foreach(name IN LISTS paths)
  file(READ ${ROOT}/${name} hex HEX)
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
  string(APPEND body "const char file_${index}[] = {${bytes} 0};\n")
  string(APPEND table "    {\"${name}\", file_${index}},\n")
  math(EXPR index "${index} + 1")
endforeach()
string(APPEND body "} // namespace\n\nconst std::vector<EmbeddedFile>& embedded_kernel_files()\n{\n")
string(APPEND body "  static const std::vector<EmbeddedFile> files = {\n${table}  };\n  return files;\n}\n} // namespace pathcl\n")
file(WRITE ${OUTPUT}.tmp "${body}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
