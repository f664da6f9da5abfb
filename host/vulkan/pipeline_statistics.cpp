#include "pipeline_statistics.h"

namespace vkrt {

double ExecutableStatistics::get(const std::string& statistic) const {
    for (const Value& v : values)
        if (v.name == statistic) return v.value;
    return -1.0;
}

std::vector<ExecutableStatistics> pipelineStatistics(const Context& context, vk::Pipeline pipeline) {
    std::vector<ExecutableStatistics> out;
    if (!context.statisticsEnabled()) return out;
    const vk::raii::Device& device = context.device();
    const std::vector<vk::PipelineExecutablePropertiesKHR> executables =
        device.getPipelineExecutablePropertiesKHR(vk::PipelineInfoKHR(pipeline));
    for (std::uint32_t i = 0; i < executables.size(); ++i) {
        ExecutableStatistics e;
        e.name = executables[i].name.data();
        for (const vk::PipelineExecutableStatisticKHR& s : device.getPipelineExecutableStatisticsKHR({pipeline, i})) {
            double value = 0.0;
            switch (s.format) {
                case vk::PipelineExecutableStatisticFormatKHR::eBool32: value = s.value.b32 ? 1.0 : 0.0; break;
                case vk::PipelineExecutableStatisticFormatKHR::eInt64: value = static_cast<double>(s.value.i64); break;
                case vk::PipelineExecutableStatisticFormatKHR::eUint64: value = static_cast<double>(s.value.u64); break;
                case vk::PipelineExecutableStatisticFormatKHR::eFloat64: value = s.value.f64; break;
            }
            e.values.push_back({s.name.data(), value});
        }
        out.push_back(std::move(e));
    }
    return out;
}

}  // namespace vkrt
