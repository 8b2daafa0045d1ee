#pragma once
// Numbers as a user types them on the command line, in a viewer script or a bench file. Every option
// reads them alike: before this, --seed 0x10 and --dmax 0x0.4p0 were read as hex while --width 0x140
// was refused, and leading spaces passed in some options only.
#include <cstdint>
#include <optional>
#include <string_view>

namespace stipple {

// An optional sign, digits with an optional decimal point, an optional exponent (8e6, 2.5E-4); nothing
// else (no hex, no spaces, no inf or nan). Nothing for other text or a value beyond double range; a value
// too small for a double reads as what it rounds to (0 or subnormal), left to the caller's range check.
std::optional<double> parse_decimal(std::string_view text);

// An optional sign and digits only, within int64.
std::optional<int64_t> parse_decimal_integer(std::string_view text);

// A size in bytes: a decimal number, bare or with k, M or G (either case; 1024, 1024^2, 1024^3): "64k",
// "64K", "1.5G", "123456". Nothing for other text, a negative size or one beyond 1e18 bytes. Options and
// environment variables read sizes through this one rule.
std::optional<uint64_t> parse_byte_size(std::string_view text);

}  // namespace stipple
