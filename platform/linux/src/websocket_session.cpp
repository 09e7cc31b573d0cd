#include "websocket_session.hpp"

#include <cstddef>
#include <utility>

namespace azt::linux_os::web {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;

namespace {
constexpr std::size_t kMaxWsMessageBytes = std::size_t{4} * 1024;
}

WsSession::WsSession(asio::ip::tcp::socket socket, std::shared_ptr<HttpServer::Shared> shared)
    : ws_(std::move(socket)), shared_(std::move(shared)) {
  websocket = true;
}

void WsSession::prepare() {
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.read_message_max(kMaxWsMessageBytes);
}

void WsSession::on_accepted() {
  shared_->ws.push_back(shared_from_this());
  push(std::make_shared<const std::string>(shared_->callbacks.state()));
  read();
}

void WsSession::push(std::shared_ptr<const std::string> text) {
  if (closed_) return;
  if (writing_) {
    next_ = std::move(text);  // replaces an older pending frame: state is idempotent
    return;
  }
  writing_ = true;
  current_ = std::move(text);
  ws_.text(true);
  ws_.async_write(
      asio::buffer(*current_),
      [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_written(ec); });
}

void WsSession::close() {
  if (closed_) return;
  closed_ = true;
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().close(ignored);
}

void WsSession::read() {
  ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if (ec) {
      self->close();
      return;
    }
    self->in_.consume(self->in_.size());
    self->read();
  });
}

void WsSession::on_written(beast::error_code ec) {
  writing_ = false;
  current_.reset();
  if (ec) {
    close();
    return;
  }
  if (next_) push(std::exchange(next_, nullptr));
}

}  // namespace azt::linux_os::web
