// A small mutation fuzzer for compilers without libFuzzer (GCC): runs LLVMFuzzerTestOneInput on
// every seed file, then on random mutations of them (byte changes, truncations, insertions,
// deletions, duplicated ranges, ASCII digit edits) for a bounded number of runs or seconds,
// with a fixed random seed so a failure reproduces. Crashes surface through the sanitizers.
// Usage: qd_fuzz_mesh_readers SEED_DIR [RUNS] [SECONDS]
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int run(const std::string& input) {
  return LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
}

std::string mutate(std::string s, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n)(rng); };
  const int edits = 1 + static_cast<int>(pick(3));
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = s.empty() ? 0 : pick(s.size() - 1);
    switch (pick(5)) {
      case 0:
        if (!s.empty()) s[at] = static_cast<char>(pick(255));
        break;
      case 1:
        s.resize(pick(s.size()));
        break;
      case 2:
        s.insert(at, 1, static_cast<char>(pick(255)));
        break;
      case 3:
        if (!s.empty()) s.erase(at, pick(16));
        break;
      case 4:
        if (!s.empty()) s.insert(at, s.substr(pick(s.size() - 1), pick(64)));
        break;
      default:
        s.insert(at, std::to_string(static_cast<long long>(rng()) >> pick(60)));
        break;
    }
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SEED_DIR [RUNS] [SECONDS]\n", argv[0]);
    return 2;
  }
  std::vector<std::string> seeds;
  for (const auto& entry : std::filesystem::directory_iterator(argv[1])) {
    std::ifstream in(entry.path(), std::ios::binary);
    seeds.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (seeds.empty()) {
    std::fprintf(stderr, "no seed files in %s\n", argv[1]);
    return 2;
  }
  const long runs = argc > 2 ? std::stol(argv[2]) : 100000;
  const double seconds = argc > 3 ? std::stod(argv[3]) : 60;
  for (const std::string& s : seeds) run(s);
  std::mt19937_64 rng(20120601);
  const auto start = std::chrono::steady_clock::now();
  long done = 0;
  for (; done < runs; ++done) {
    if (done % 256 == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds)
      break;
    run(mutate(seeds[rng() % seeds.size()], rng));
  }
  std::printf("fuzz: %zu seeds, %ld mutated inputs, no crash\n", seeds.size(), done);
  return 0;
}
