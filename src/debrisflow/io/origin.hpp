#pragma once
#include <map>
#include <string>

namespace debrisflow::io {

// Where a block of the case file and each of its keys sit (file:line:column), kept by a spec
// so that checks made after reading (builders, derived quantities, resource estimates) name
// the file, the line and the key as the reader's own errors do.
class Origin {
public:
    Origin() = default;
    // "case.toml:12:3: key 'fluid.0.max'"; for a key the block does not hold, the block's own
    // position with the key's full name.
    std::string at(const std::string& key) const;
    // "case.toml:10:1: [fluid.0]"
    std::string block() const;

private:
    friend class ConfigTable;
    struct Position {
        long line = 0, column = 0;
    };
    std::string format(const Position& p, const std::string& what) const;
    std::string file_, prefix_;
    Position block_;
    std::map<std::string, Position> keys_;
};

} // namespace debrisflow::io
