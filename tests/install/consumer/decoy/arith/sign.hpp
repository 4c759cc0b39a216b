// A user's own header of the same name as one of cmx's (consumer/CMakeLists.txt): never included.
#error "a cmx header included the consumer's arith/sign.hpp instead of its own"
