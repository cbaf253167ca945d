// The check of the standalone kernel tests (Testing/Kernel): EXPECT(condition, message) counts
// the checks and the failures and prints the first 25 failures with their file and line; a
// test's main() returns non-zero when pcstest::Failures > 0.
#ifndef pcsKernelTest_h
#define pcsKernelTest_h

#include <iostream>

namespace pcstest
{
inline int Failures = 0;
inline long long Checks = 0;
} // namespace pcstest

#define EXPECT(condition, message)                                                                 \
  do                                                                                               \
  {                                                                                                \
    ++pcstest::Checks;                                                                             \
    if (!(condition))                                                                              \
    {                                                                                              \
      if (pcstest::Failures++ < 25)                                                                \
      {                                                                                            \
        std::cerr << __FILE__ << ":" << __LINE__ << ": " #condition " -- " << message              \
                  << std::endl;                                                                    \
      }                                                                                            \
    }                                                                                              \
  } while (false)

#endif
