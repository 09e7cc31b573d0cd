// The UDP datagram server against real sockets on loopback: a datagram is handed on only whole
// (docs/reliability.md "Hardening, round three" row 6: a 1,610-byte datagram of receiver lines had
// been cut at the buffer, and its cut last line read as a power of -4.0 dB). The loop runs until
// what a test waits for has happened.
#include "azt/linux/udp_datagram_server.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "run_until.hpp"

namespace azt::linux_os {
namespace {

namespace asio = boost::asio;
using asio::ip::udp;

struct Received {
  std::vector<std::string> datagrams;
  std::vector<std::size_t> oversized_bytes;
};

class UdpServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto server = UdpDatagramServer::open(io_, "test", "127.0.0.1", 0, 0,
                                          [this](std::string_view datagram, const std::string&) {
                                            got_.datagrams.emplace_back(datagram);
                                            return std::string{};
                                          });
    ASSERT_TRUE(server) << server.error().message;
    server_ = std::move(server).value();
    server_->on_oversized(
        [this](std::size_t bytes, const std::string&) { got_.oversized_bytes.push_back(bytes); });
    sender_.open(udp::v4());
  }

  void send(const std::string& datagram) {
    sender_.send_to(asio::buffer(datagram),
                    udp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
  }

  [[nodiscard]] std::size_t events() const {
    return got_.datagrams.size() + got_.oversized_bytes.size();
  }

  static std::string lines_of(std::size_t bytes) {
    std::string text;
    while (text.size() + 7 <= bytes) text += "-45.25\n";
    text.resize(bytes, ' ');
    return text;
  }

  asio::io_context io_;
  std::unique_ptr<UdpDatagramServer> server_;
  udp::socket sender_{io_};
  Received got_;
};

TEST_F(UdpServerTest, DatagramOverTheLimitIsDroppedWholeAndReportedWithItsRealLength) {
  send(lines_of(1610));
  ASSERT_TRUE(run_until(io_, [&] { return events() == 1; }));
  EXPECT_TRUE(got_.datagrams.empty()) << "a cut datagram was handed on";
  ASSERT_EQ(got_.oversized_bytes.size(), 1U);
  EXPECT_EQ(got_.oversized_bytes[0], 1610U);
}

TEST_F(UdpServerTest, DatagramAtTheLimitIsHandedOnWhole) {
  const std::string exact = lines_of(UdpDatagramServer::kMaxDatagramBytes);
  send(exact);
  ASSERT_TRUE(run_until(io_, [&] { return events() == 1; }));
  ASSERT_EQ(got_.datagrams.size(), 1U);
  EXPECT_EQ(got_.datagrams[0], exact);
}

TEST_F(UdpServerTest, ServerKeepsReceivingAfterAnOversizedDatagram) {
  send(lines_of(4000));
  send("-45.25\n");
  ASSERT_TRUE(run_until(io_, [&] { return events() == 2; }));
  ASSERT_EQ(got_.datagrams.size(), 1U);
  EXPECT_EQ(got_.datagrams[0], "-45.25\n");
  EXPECT_EQ(got_.oversized_bytes, std::vector<std::size_t>{4000U});
}

}  // namespace
}  // namespace azt::linux_os
