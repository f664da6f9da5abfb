# cmake -DINPUT=x.spv -DOUTPUT=x.spv.inc -P embed_spirv.cmake
# Writes the SPIR-V words of INPUT as a comma-separated list of uint32 literals, to be #included
# inside an array initialiser. SPIR-V is a stream of little-endian 32-bit words, so each group of
# four bytes is reversed into one hexadecimal literal.
file(READ ${INPUT} hex HEX)
string(LENGTH "${hex}" length)
math(EXPR remainder "${length} % 8")
if(length EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${INPUT}: not a SPIR-V module (size is not a positive multiple of 4 bytes)")
endif()
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u,\n" words "${hex}")
file(WRITE ${OUTPUT} "${words}")
