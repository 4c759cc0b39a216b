// A user's own header of the same name as one of cmx's (consumer/CMakeLists.txt): never included.
#error "a cmx header included the consumer's kernel/determinant.hpp instead of its own"
