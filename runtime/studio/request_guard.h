#pragma once
// Which requests the studio answers: only those addressed to its own host and port, and, when a
// browser says where the page came from (Origin), only from its own page. A page on another site
// must not drive it, even through a name that resolves to 127.0.0.1 (DNS rebinding).
#include <optional>
#include <string>
#include <vector>

namespace fg::studio {

class RequestGuard {
public:
    // `bind_host` is the address the server listens on; loopback names are accepted for a loopback
    // address ("localhost", "127.0.0.1", "[::1]").
    RequestGuard(const std::string& bind_host, int port);

    // Empty when the request may go on, else the reason it is refused (a 403's body).
    std::optional<std::string> refuse(const std::string& host_header, const std::string& origin_header) const;

    const std::vector<std::string>& allowed_hosts() const { return hosts_; }

private:
    std::vector<std::string> hosts_;   // "host:port" as a Host header spells it
};

}  // namespace fg::studio
