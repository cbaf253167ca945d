// Replays fuzz inputs through a fuzz target without libFuzzer: every file named on the command
// line, or every file of the directories named, is passed to LLVMFuzzerTestOneInput. This is the
// ctest regression test of the saved corpus (Testing/Fuzz/corpus/<target>/): inputs that once
// broke an invariant, plus seeds of each input family.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char* argv[])
{
  namespace fs = std::filesystem;
  int files = 0;
  for (int i = 1; i < argc; ++i)
  {
    std::vector<fs::path> paths;
    if (!fs::exists(argv[i]))
    {
      std::fprintf(stderr, "no such file or directory: %s\n", argv[i]);
      return 1;
    }
    if (fs::is_directory(argv[i]))
    {
      for (const auto& entry : fs::directory_iterator(argv[i]))
      {
        paths.push_back(entry.path());
      }
    }
    else
    {
      paths.emplace_back(argv[i]);
    }
    for (const fs::path& path : paths)
    {
      std::ifstream in(path, std::ios::binary);
      const std::vector<uint8_t> bytes(
        (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
      ++files;
    }
  }
  std::printf("%d input(s) replayed, every invariant held\n", files);
  return files > 0 ? 0 : 1;
}
