#pragma once
// The GPIO seam on the kernel's GPIO character device through libgpiod 1.6 (Debian 12): outputs
// are line requests held for the provider's lifetime; inputs request both edge events and their
// event file descriptors are watched by the io_context, so an edge is acted on at once rather
// than at the next control tick.

#include <memory>
#include <string>

#include "azt/linux/gpio.hpp"

namespace boost::asio {
class io_context;
}  // namespace boost::asio

namespace azt::linux_os {

std::unique_ptr<GpioProvider> make_libgpiod_provider(boost::asio::io_context& io,
                                                     std::string consumer = "azeltrack");

}  // namespace azt::linux_os
