// printf-style formatting into a std::string, for the summaries the core writes for the log.
#ifndef VCG_EXT_COMMON_FORMAT_H
#define VCG_EXT_COMMON_FORMAT_H

#include <cstdarg>
#include <cstdio>
#include <string>

namespace vcg_ext {

inline std::string Format(const char *format, ...) __attribute__((format(printf, 1, 2)));
inline std::string Format(const char *format, ...)
{
    va_list args, copy;
    va_start(args, format);
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string s(n > 0 ? size_t(n) : 0, '\0');
    if (n > 0) std::vsnprintf(&s[0], size_t(n) + 1, format, args);
    va_end(args);
    return s;
}

}  // namespace vcg_ext

#endif
