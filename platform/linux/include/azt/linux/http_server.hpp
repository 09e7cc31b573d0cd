#pragma once
// The console's HTTP and WebSocket transport (Boost.Beast on the daemon's io_context). It knows
// nothing of the API: every request goes to a handler as a HttpRequest (its text made valid UTF-8
// first), and WebSocket clients get the same state text pushed at a fixed period. Bounded: 64 KiB
// bodies unless the handler's body_limit lets a route take more (413) or streams it to a sink,
// 8 KiB headers (431), 30 s idle HTTP connections, one pending frame per slow WebSocket client
// (older frames are dropped, never queued).
//
// The operator can always reach STOP (docs/reliability.md "Hardening" row 5): at most
// kMaxPerAddress connections from one address; at most kMaxConnections in all, and when they are
// taken a new connection evicts the oldest one that has shown no session, so a logged-in console is
// never pushed out by strangers; WebSockets without a session share a pool of
// kMaxAnonymousWebSockets, and WebSockets of any kind take at most kMaxWebSockets, so requests (a
// STOP) always find room. An exception from a handler closes that one connection with a log line;
// the server carries on.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "azt/linux/asio.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

struct HttpReply {
  unsigned status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;
};

/// Takes a request's body as it arrives, for a route whose body is too large to hold whole (a
/// package upload): the transport reads the next chunk only once `write` has
/// called `next`, so one chunk at a time is in memory. `next` with a reply refuses the rest of
/// the body: the reply is sent, what the client still sends is dropped, the connection closes.
class HttpBodySink {
 public:
  using Next = std::function<void(std::optional<HttpReply> refusal)>;
  HttpBodySink() = default;
  HttpBodySink(const HttpBodySink&) = delete;
  HttpBodySink& operator=(const HttpBodySink&) = delete;
  virtual ~HttpBodySink() = default;
  /// Runs on the loop; `next` runs on the loop exactly once, at once or later.
  virtual void write(std::string chunk, Next next) = 0;
};

struct HttpRequest {
  std::string method;  ///< "GET", "POST", …
  std::string path;    ///< without the query
  std::string query;   ///< after '?', undecoded
  std::string body;
  std::string origin;         ///< the Origin header, "" when absent
  std::string host;           ///< the Host header
  std::string cookie;         ///< the whole Cookie header
  std::string csrf;           ///< X-CSRF-Token
  std::string authorization;  ///< the whole Authorization header
  std::string client;         ///< the peer's address (no port): the login rate limit's key
  bool websocket = false;     ///< an upgrade request for /ws
  /// It carries a proxy's header (Forwarded, X-Forwarded-*, X-Real-IP, Via): whoever sent it
  /// first is elsewhere, whatever `client` says, so it is never "from this machine".
  bool forwarded = false;
  /// The sink that took the body as it arrived (`body` is then empty), when the route's
  /// HttpServer::BodyAllowance gave one.
  std::shared_ptr<HttpBodySink> streamed_body;
};

class HttpServer {
 public:
  using Respond = std::function<void(HttpReply)>;
  /// Answers through `respond` exactly once, at once or later (on the same thread). The request
  /// is the handler's (moved in: an upload's body is never copied on the loop).
  using Handler = std::function<void(HttpRequest, const Respond&)>;
  /// For an upgrade request: nullopt to accept the WebSocket, or the refusal to send.
  using UpgradeCheck = std::function<std::optional<HttpReply>(const HttpRequest&)>;
  /// Whether a request shows a valid session (cookie or bearer token).
  using SessionCheck = std::function<bool(const HttpRequest&)>;
  /// What may follow a request's head: a body of up to max_bytes, or, with a refusal, nothing:
  /// the refusal is sent at once (what the client still sends is read and dropped, so that it
  /// reads the answer rather than a reset connection) and the connection closed.
  struct BodyAllowance {
    std::size_t max_bytes = kMaxBodyBytes;
    std::optional<HttpReply> refusal;
    /// Kept by the connection until the request is answered or the connection closes: a
    /// handler's token for "one at a time" decided from the head (a 60 MiB upload's body is
    /// read only while it holds the one slot).
    std::shared_ptr<const void> hold;
    /// Given: the body goes to it chunk by chunk (never held whole) and the handler gets the
    /// request with HttpRequest::streamed_body set once the last chunk is taken.
    std::shared_ptr<HttpBodySink> sink;
  };
  /// Decides the allowance from the head alone (HttpRequest::body is empty: not read yet).
  using BodyLimit = std::function<BodyAllowance(const HttpRequest&)>;
  using StateText = std::function<std::string()>;
  using Log = std::function<void(const std::string&)>;

  struct Callbacks {
    Handler handler;
    UpgradeCheck upgrade_check;
    SessionCheck has_session;
    StateText state;
    BodyLimit body_limit;  ///< null: kMaxBodyBytes for every request
    Log log;
  };

  /// A request body's size unless Callbacks::body_limit allows more (413 beyond).
  static constexpr std::size_t kMaxBodyBytes = std::size_t{64} * 1024;
  static constexpr std::size_t kMaxConnections = 128;
  static constexpr std::size_t kMaxPerAddress = 32;
  static constexpr std::size_t kMaxAnonymousWebSockets = 16;
  /// Live views of any kind: the other half of kMaxConnections stays for requests.
  static constexpr std::size_t kMaxWebSockets = 64;

  static Result<std::unique_ptr<HttpServer>> open(boost::asio::io_context& io,
                                                  const std::string& bind_address,
                                                  unsigned short port, Callbacks callbacks,
                                                  double push_period_s);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  /// Pushes the state to every WebSocket client now (after a change), besides the periodic push.
  void push_now();
  [[nodiscard]] unsigned short port() const;
  [[nodiscard]] std::size_t websockets() const;
  /// Open connections, HTTP and WebSocket.
  [[nodiscard]] std::size_t connections() const;
  void close();

  struct Shared;  ///< what sessions share with the server (outlives it while they run)

 private:
  HttpServer(boost::asio::io_context& io, std::shared_ptr<Shared> shared, double push_period_s);
  void accept_next();
  /// Caps and eviction (the class comment), then an HttpSession for `socket`.
  void admit(boost::asio::ip::tcp::socket socket);
  void arm_push();
  void broadcast();

  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer push_timer_;
  boost::asio::steady_timer::duration push_period_;
  std::shared_ptr<Shared> shared_;
};

}  // namespace azt::linux_os
