#include "studio/request_guard.h"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace fg::studio {

namespace {
std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool is_loopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }
}  // namespace

RequestGuard::RequestGuard(const std::string& bind_host, int port) {
    auto add = [&](const std::string& host) {
        bool ipv6 = host.find(':') != std::string::npos;
        hosts_.push_back(fmt::format("{}:{}", ipv6 ? "[" + host + "]" : host, port));
    };
    if (is_loopback(bind_host)) {
        for (const char* h : {"127.0.0.1", "localhost", "::1"}) add(h);
    } else {
        add(lower(bind_host));
    }
}

std::optional<std::string> RequestGuard::refuse(const std::string& host_header, const std::string& origin_header) const {
    auto allowed = [&](const std::string& host) { return std::find(hosts_.begin(), hosts_.end(), lower(host)) != hosts_.end(); };
    if (!allowed(host_header))
        return fmt::format("refused: Host '{}' is not this studio ({})", host_header, hosts_.front());
    // Browsers send Origin on cross-site requests and on every POST; a same-origin GET may omit it.
    if (!origin_header.empty()) {
        const std::string scheme = "http://";
        std::string origin = lower(origin_header);
        if (origin.rfind(scheme, 0) != 0 || !allowed(origin.substr(scheme.size())))
            return fmt::format("refused: Origin '{}' is not this studio's page", origin_header);
    }
    return std::nullopt;
}

}  // namespace fg::studio
