#pragma once
// True when the consumer's compile flags let the compiler fuse a multiply and a subtraction.
bool consumer_flags_contract();
