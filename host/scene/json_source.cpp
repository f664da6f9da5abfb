#include "json_source.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iterator>
#include <optional>

#include "diagnostics.h"
#include "number_text.h"

namespace vkrt {

namespace {

// Iterates over the text like a const char*, and writes how many bytes the parser has taken
// into *consumed at every step. nlohmann's lexer reads through its input adapter strictly in
// order, one byte per ++; after a number it has taken one byte of lookahead (which it keeps,
// unread, for the next token).
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* base, const char* at, std::size_t* consumed) : base_(base), at_(at), consumed_(consumed) {}
    reference operator*() const { return *at_; }
    CountingIterator& operator++() {
        ++at_;
        *consumed_ = static_cast<std::size_t>(at_ - base_);
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
    bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

private:
    const char* base_;
    const char* at_;
    std::size_t* consumed_;
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNumberChar(char c) { return isDigit(c) || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'; }

// Deeper than any scene (the course's files nest 7 levels); see SpanRecordingBuilder::open.
constexpr std::size_t kMaxDepth = 64;
constexpr int kTooDeep = -1;  // ParseFailure::id of a document nested deeper than kMaxDepth

struct ParseFailure {
    std::size_t position = 0;   // nlohmann's chars_read_total
    std::string lastToken;
    std::string what;
    int id = 0;
    std::string valuePath;      // the path the failing value would have had
};

// Builds the DOM like nlohmann's own json_sax_dom_parser, recording spans as it goes.
class SpanRecordingBuilder : public nlohmann::json_sax<Json> {
public:
    SpanRecordingBuilder(const std::string& text, const std::size_t& consumed, Json& root,
                         std::unordered_map<std::string, JsonSource::Span>& spans, std::vector<JsonSource::RepeatedKey>& repeated)
        : text_(text), consumed_(consumed), root_(root), spans_(spans), repeated_(repeated) {}

    std::optional<ParseFailure> failure;

    bool null() override { return scalar(nullptr, literalBegin(4)); }
    bool boolean(bool value) override { return scalar(value, literalBegin(value ? 4 : 5)); }
    bool number_integer(number_integer_t value) override { return scalar(value, numberBegin()); }
    bool number_unsigned(number_unsigned_t value) override { return scalar(value, numberBegin()); }
    bool number_float(number_float_t value, const string_t&) override { return scalar(value, numberBegin()); }
    bool string(string_t& value) override { return scalar(std::move(value), stringBegin()); }
    bool binary(binary_t&) override { return true; }  // not produced by JSON text

    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override {
        if (discardDepth_ > 0) return true;
        pendingKey_ = key;
        pendingKeyAt_ = stringBeginAt(consumed_);
        Json& object = *stack_.back().value;
        if (object.contains(key)) {
            repeated_.push_back({memberPath(stack_.back().path, key), pendingKeyAt_});
            discardNext_ = true;
        }
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::detail::exception& ex) override {
        failure = ParseFailure{position, lastToken, ex.what(), ex.id, discardDepth_ > 0 ? std::string() : nextPath()};
        return false;
    }

private:
    struct Open {
        Json* value;
        std::string path;
        std::size_t elements = 0;
    };

    // Offsets of the value just read, from what the parser has consumed (see CountingIterator).
    std::ptrdiff_t literalBegin(std::size_t length) const { return static_cast<std::ptrdiff_t>(consumed_ - length); }
    std::ptrdiff_t numberBegin() {
        std::size_t end = consumed_;
        if (end > 0 && !isDigit(text_[end - 1])) --end;  // the lookahead byte; a number ends in a digit
        lastEnd_ = end;
        std::size_t begin = end;
        while (begin > 0 && isNumberChar(text_[begin - 1])) --begin;
        return static_cast<std::ptrdiff_t>(begin);
    }
    // The opening quote of the string whose closing quote is the last byte before `end`.
    std::ptrdiff_t stringBeginAt(std::size_t end) const {
        std::size_t at = end >= 2 ? end - 2 : 0;
        for (; at > 0; --at) {
            if (text_[at] != '"') continue;
            std::size_t backslashes = 0;
            while (at > backslashes && text_[at - 1 - backslashes] == '\\') ++backslashes;
            if (backslashes % 2 == 0) break;
        }
        return static_cast<std::ptrdiff_t>(at);
    }
    std::ptrdiff_t stringBegin() { return stringBeginAt(consumed_); }

    std::string nextPath() const {
        if (stack_.empty()) return "";
        const Open& top = stack_.back();
        return top.value->is_array() ? elementPath(top.path, top.elements) : memberPath(top.path, pendingKey_);
    }

    // Puts a new value where the parser is (the root, an array's end, the pending key) and
    // records its span; nullptr when it is a repeated key's value, which is dropped.
    Json* place(Json value, std::ptrdiff_t begin, std::ptrdiff_t end, std::string& path) {
        path = nextPath();
        Json* placed = nullptr;
        JsonSource::Span span{-1, begin, end};
        if (stack_.empty()) {
            root_ = std::move(value);
            placed = &root_;
        } else if (Open& top = stack_.back(); top.value->is_array()) {
            top.value->push_back(std::move(value));
            placed = &top.value->back();
            ++top.elements;
        } else {
            span.key = pendingKeyAt_;
            if (std::exchange(discardNext_, false)) return nullptr;
            placed = &(*top.value)[pendingKey_];
            *placed = std::move(value);
        }
        spans_[path] = span;
        return placed;
    }

    template <typename Value>
    bool scalar(Value&& value, std::ptrdiff_t begin) {
        if (discardDepth_ > 0) return true;
        const std::ptrdiff_t end = lastEnd_ != npos ? static_cast<std::ptrdiff_t>(lastEnd_) : static_cast<std::ptrdiff_t>(consumed_);
        lastEnd_ = npos;
        std::string path;
        place(Json(std::forward<Value>(value)), begin, end, path);
        return true;
    }

    bool open(Json container) {
        if (stack_.size() + static_cast<std::size_t>(discardDepth_) >= kMaxDepth) {
            // Each level's path repeats its parent's, so unbounded depth would cost quadratic memory.
            failure = ParseFailure{consumed_, "", "", kTooDeep, ""};
            return false;
        }
        if (discardDepth_ > 0 || (discardNext_ && !stack_.empty() && stack_.back().value->is_object())) {
            discardNext_ = false;
            ++discardDepth_;
            return true;
        }
        const auto begin = static_cast<std::ptrdiff_t>(consumed_) - 1;
        std::string path;
        Json* placed = place(std::move(container), begin, begin + 1, path);
        stack_.push_back({placed, std::move(path)});
        return true;
    }

    bool close() {
        if (discardDepth_ > 0) {
            --discardDepth_;
            return true;
        }
        spans_[stack_.back().path].end = static_cast<std::ptrdiff_t>(consumed_);
        stack_.pop_back();
        return true;
    }

    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    const std::string& text_;
    const std::size_t& consumed_;
    Json& root_;
    std::unordered_map<std::string, JsonSource::Span>& spans_;
    std::vector<JsonSource::RepeatedKey>& repeated_;
    std::vector<Open> stack_;
    std::string pendingKey_;
    std::ptrdiff_t pendingKeyAt_ = -1;
    bool discardNext_ = false;   // the pending key is a repeat: its value is dropped
    int discardDepth_ = 0;       // inside a dropped container
    std::size_t lastEnd_ = npos; // a number's end, set by numberBegin
};

// nlohmann's "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
// -> line 2, column 7 and "syntax error ...".
bool splitLibraryMessage(const std::string& what, int& line, int& column, std::string& description) {
    const std::size_t at = what.find(" at line ");
    if (at == std::string::npos) return false;
    if (std::sscanf(what.c_str() + at, " at line %d, column %d", &line, &column) != 2) return false;
    const std::size_t colon = what.find(": ", at);
    description = colon == std::string::npos ? what : what.substr(colon + 2);
    return true;
}

}  // namespace

std::string memberPath(const std::string& object, const std::string& key) { return object.empty() ? key : object + "." + key; }

std::string elementPath(const std::string& array, std::size_t index) { return array + "[" + std::to_string(index) + "]"; }

JsonSource::JsonSource(std::string path, const std::string& text) : path_(std::move(path)), text_(text), lines_(text_) {
    std::size_t consumed = 0;
    SpanRecordingBuilder builder(text_, consumed, root_, spans_, repeated_);
    const CountingIterator first(text_.data(), text_.data(), &consumed);
    const CountingIterator last(text_.data(), text_.data() + text_.size(), &consumed);
    if (Json::sax_parse(first, last, &builder, nlohmann::json::input_format_t::json, /*strict=*/true)) return;

    const ParseFailure failure = builder.failure.value_or(ParseFailure{consumed, "", "unknown error", 0, ""});
    if (failure.id == kTooDeep) {
        const auto at = static_cast<std::ptrdiff_t>(failure.position > 0 ? failure.position - 1 : 0);
        throw SceneError({path_, lineOf(at), "json", "nested deeper than " + std::to_string(kMaxDepth) + " levels, not a scene",
                          "", columnOf(at)});
    }
    if (failure.id == 406) {
        // out_of_range.406, "number overflow parsing '1e400'": the token ends where the lexer stopped.
        const auto begin = static_cast<std::ptrdiff_t>(failure.position - std::min(failure.position, failure.lastToken.size()));
        throw SceneError({path_, lineOf(begin), failure.valuePath.empty() ? "json" : failure.valuePath, kNotAFiniteFloat,
                          failure.lastToken, columnOf(begin)});
    }
    int line = 0, column = 0;
    std::string description;
    if (!splitLibraryMessage(failure.what, line, column, description)) {
        const auto last = static_cast<std::ptrdiff_t>(failure.position > 0 ? failure.position - 1 : 0);
        line = lineOf(last);
        column = columnOf(last);
        description = failure.what;
    }
    // As XML: the library's description, then the text from the byte it stopped at.
    const auto stop = static_cast<std::size_t>(failure.position > 0 ? failure.position - 1 : 0);
    std::string snippet = "end of file";
    if (stop < text_.size()) {
        const std::size_t lineEnd = std::min(text_.find_first_of("\r\n", stop), text_.size());
        snippet = text_.substr(stop, std::min<std::size_t>(lineEnd - stop, 40));
    }
    throw SceneError({path_, line, "json", "malformed JSON (" + description + ") at", snippet, column});
}

const JsonSource::Span* JsonSource::spanOf(const std::string& path) const {
    const auto found = spans_.find(path);
    return found == spans_.end() ? nullptr : &found->second;
}

std::string JsonSource::textOf(const std::string& path) const {
    const Span* span = spanOf(path);
    if (!span || span->end <= span->begin) return "";
    return text_.substr(static_cast<std::size_t>(span->begin), static_cast<std::size_t>(span->end - span->begin));
}

}  // namespace vkrt
