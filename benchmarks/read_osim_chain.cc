// Reading a generated chain of n bodies, n pin joints (one coordinate each) and n markers, for
// n = 1000 .. 16000: every name lookup of the reader is indexed, so the time should grow
// linearly with n. Google Benchmark fits the complexity (BigO and RMS lines of the report);
// a quadratic lookup shows as O(N^2) and takes seconds at n = 16000.
#include <benchmark/benchmark.h>
#include <sinew/io/osim_reader.h>

#include <string>

namespace {

// An OpenSim 4.0 model: ground -> b0 -> b1 -> ... -> b(n-1), pins j0..j(n-1) with coordinates
// q0..q(n-1), and one marker per body.
std::string ChainModel(int n) {
  std::string bodies, joints, markers;
  for (int i = 0; i < n; ++i) {
    const std::string b = "b" + std::to_string(i);
    const std::string parent = i == 0 ? "/ground" : "/bodyset/b" + std::to_string(i - 1);
    bodies += "<Body name=\"" + b + "\"><mass>1</mass></Body>\n";
    joints += "<PinJoint name=\"j" + std::to_string(i) + "\"><socket_parent_frame>" + parent +
              "</socket_parent_frame><socket_child_frame>/bodyset/" + b +
              "</socket_child_frame><coordinates><Coordinate name=\"q" + std::to_string(i) +
              "\"/></coordinates></PinJoint>\n";
    markers += "<Marker name=\"m" + std::to_string(i) + "\"><socket_parent_frame>/bodyset/" + b +
               "</socket_parent_frame></Marker>\n";
  }
  return "<OpenSimDocument Version=\"40000\"><Model name=\"chain\"><Ground name=\"ground\"/>\n"
         "<BodySet><objects>\n" +
         bodies + "</objects></BodySet>\n<JointSet><objects>\n" + joints +
         "</objects></JointSet>\n<MarkerSet><objects>\n" + markers +
         "</objects></MarkerSet></Model></OpenSimDocument>\n";
}

void BM_ReadOsimChain(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string text = ChainModel(n);
  for (auto _ : state) {
    sinew::model::ModelSpec spec = sinew::io::ReadOsimString(text, "chain.osim");
    if (spec.bodies.size() != static_cast<size_t>(n + 1)) state.SkipWithError("wrong body count");
    benchmark::DoNotOptimize(spec);
  }
  state.SetComplexityN(n);
}
BENCHMARK(BM_ReadOsimChain)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Arg(8000)
    ->Arg(16000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();

}  // namespace
