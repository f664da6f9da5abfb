#include "validation_log.h"

namespace vkrt {

void ValidationLog::record(std::string message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
}

std::size_t ValidationLog::count() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

std::string ValidationLog::joined() const {
    std::lock_guard lock(mutex_);
    std::string all;
    for (const std::string& m : messages_) {
        all += m;
        all += '\n';
    }
    return all;
}

}  // namespace vkrt
