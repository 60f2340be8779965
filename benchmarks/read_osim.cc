// Reading Rajagopal2016.osim (875 KB, 22 bodies, 80 muscles) into the spec: goal < 10 ms median
// (Release). Also the XML parse alone, to see what the reader adds on top of pugixml.
#include <benchmark/benchmark.h>
#include <sinew/io/internal/xml_document.h>
#include <sinew/io/osim_reader.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

const std::string kRajagopal = std::string(SINEW_TEST_DATA_DIR) +
                               "/opensim-org/opensim-models/Models/Rajagopal/Rajagopal2016.osim";

std::string Slurp(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return std::move(buffer).str();
}

// From the file on disk, as `sinew inspect` does.
void BM_ReadOsimRajagopal2016(benchmark::State& state) {
  const size_t bytes = Slurp(kRajagopal).size();
  for (auto _ : state) {
    sinew::model::ModelSpec spec = sinew::io::ReadOsim(kRajagopal);
    benchmark::DoNotOptimize(spec);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_ReadOsimRajagopal2016)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The XML parse alone (pugixml plus the comment pre-pass and line index).
void BM_ParseXmlRajagopal2016(benchmark::State& state) {
  const std::string text = Slurp(kRajagopal);
  for (auto _ : state) {
    sinew::io::internal::XmlDocument doc =
        sinew::io::internal::XmlDocument::Parse(text, kRajagopal);
    benchmark::DoNotOptimize(doc);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseXmlRajagopal2016)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
