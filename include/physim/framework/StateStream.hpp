#pragma once
// What a Simulation subclass writes of its own members into a snapshot file (Simulation::writeState) and reads back
// (Simulation::readState): numbers in the order written, as bytes (little-endian, bit for bit), read back in the
// same order. The byte-level twin of saveState/restoreState, which hold a std::any in memory.

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace physim {

class StateWriter {
public:
    void putDouble(double v);
    void putInt(std::int64_t v);
    void putBool(bool v);
    /// The count, then the values.
    void putDoubles(const std::vector<double>& v);
    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
};

/// Reads what a StateWriter wrote; reading past the end throws std::runtime_error (the file and the subclass
/// disagree about what was written).
class StateReader {
public:
    explicit StateReader(std::string bytes) : bytes_(std::move(bytes)) {}
    double getDouble();
    std::int64_t getInt();
    bool getBool();
    std::vector<double> getDoubles();
    /// Bytes not read yet.
    std::size_t left() const { return bytes_.size() - at_; }

private:
    void take(void* to, std::size_t n);
    std::string bytes_;
    std::size_t at_ = 0;
};

}  // namespace physim
