# Turns a SPIR-V binary (IN) into a comma-separated list of 32-bit words (OUT) for #include, 16
# words a line. Whole-string regular expressions: a loop over substrings copies the string at
# each word and took minutes for a 200 KB shader.
file(READ ${IN} hex HEX)
# SPIR-V is little-endian: reverse the four bytes of each word.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1," words "${hex}")
set(word "0x........,")
string(REPEAT "${word}" 16 line)
string(REGEX REPLACE "(${line})" "\\1\n" words "${words}")
file(WRITE ${OUT} "${words}\n")
