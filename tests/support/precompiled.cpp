// Compiled once with the test suite's precompiled header (tests/CMakeLists.txt), which every
// test target then reuses.
