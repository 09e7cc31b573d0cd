// The operator's NTP servers (docs/time.md): names and addresses accepted, anything that could
// smuggle a chrony directive refused, and the sources file written and read back.
#include "azt/timekeeping/ntp_servers.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace azt::timekeeping {
namespace {

TEST(NtpServers, NamesAndAddressesAreAccepted) {
  for (const char* ok : {"pool.ntp.org", "ntp1.example-isp.net", "192.168.1.10", "fd00::1",
                         "2001:db8::123", "time", " de.pool.ntp.org "}) {
    const auto r = check_ntp_server(ok);
    ASSERT_TRUE(r) << ok << ": " << r.error().message;
  }
  EXPECT_EQ(check_ntp_server(" de.pool.ntp.org ").value(), "de.pool.ntp.org");
}

TEST(NtpServers, AnythingThatCouldBeADirectiveIsRefused) {
  for (const char* bad : {"", "   ", "pool.ntp.org iburst", "a.example\nallow all",
                          "a.example\rallow", "-bad.example", "bad-.example", "a..example",
                          "a.example.", "x;rm", "ünïcode.example", "server:123"}) {
    EXPECT_FALSE(check_ntp_server(bad)) << "accepted: " << bad;
  }
  EXPECT_FALSE(check_ntp_server(std::string(64, 'a') + ".example")) << "a 64-character label";
  EXPECT_FALSE(check_ntp_server(std::string(250, 'a'))) << "longer than 253 in all";
  const auto r = check_ntp_server("a.example\nallow all");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("not a host name"), std::string::npos);
}

TEST(NtpServers, TheListIsBoundedAndHasNoTwins) {
  EXPECT_TRUE(check_ntp_servers({}));
  EXPECT_FALSE(check_ntp_servers({"a.example", "b.example", "a.example"}));
  EXPECT_FALSE(check_ntp_servers(std::vector<std::string>(kMaxNtpServers + 1, "x")));
  EXPECT_FALSE(check_ntp_servers({"a.example", "bad name"}));
  const auto ok = check_ntp_servers({"a.example", " b.example"});
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok.value(), (std::vector<std::string>{"a.example", "b.example"}));
}

TEST(NtpServers, TheSourcesFileReadsBack) {
  const std::vector<std::string> servers{"192.168.1.10", "europe.pool.ntp.org", "fd00::1"};
  const std::string text = chrony_sources_text(servers);
  EXPECT_NE(text.find("server 192.168.1.10 iburst\n"), std::string::npos);
  EXPECT_NE(text.find("pool europe.pool.ntp.org iburst\n"), std::string::npos);
  EXPECT_EQ(servers_in_sources(text), servers);
  EXPECT_TRUE(servers_in_sources(chrony_sources_text({})).empty());
  // A file edited by hand: other directives and comments are not servers.
  EXPECT_EQ(servers_in_sources("# server old.example\n  server\tb.example  iburst\npeer c\n"),
            std::vector<std::string>{"b.example"});
}

}  // namespace
}  // namespace azt::timekeeping
