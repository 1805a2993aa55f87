#pragma once
/// libFuzzer entry point of each harness (fuzz_yaml.cpp, fuzz_msh.cpp). The same sources
/// build into a libFuzzer binary (BIPOT_FUZZ=ON, clang) and into a corpus replayer
/// (replay_main.cpp, any compiler) that the test suite runs on the checked-in corpus.

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
