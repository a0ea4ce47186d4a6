#include "drivers/sweep_plan.h"

#include "opf/io/json_text.h"

#include <string>
#include <string_view>

namespace opf::experiments {

void write_sweep_plan(std::ostream& json, const SweepSpec& spec, const std::vector<SweepRun>& runs,
                      const std::filesystem::path& out) {
  const std::filesystem::path root = std::filesystem::absolute(out).lexically_normal();
  json << "{\n  \"name\": " << json_string(spec.name)
       << ",\n  \"sweep\": " << json_string(std::filesystem::absolute(spec.file).string())
       << ",\n  \"out\": " << json_string(root.string())
       << ",\n  \"table\": " << json_string((root / (spec.name + ".csv")).string())
       << ",\n  \"runs\": [";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SweepRun& run = runs[i];
    json << (i ? ",\n" : "\n") << "    {\"directory\": " << json_string(run.directory.string())
         << ", \"result\": " << json_string(run.result_file().string())
         << ", \"settings_yaml\": " << json_string(run.settings_yaml) << ", \"arguments\": [";
    const std::vector<std::string> args = run.arguments(root);
    for (std::size_t a = 0; a < args.size(); ++a) json << (a ? ", " : "") << json_string(args[a]);
    json << "]}";
  }
  json << "\n  ]\n}\n";
}

}  // namespace opf::experiments
