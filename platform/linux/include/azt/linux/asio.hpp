#pragma once
// The one way to include Boost.Asio: Boost 1.74's headers use std::exchange without including
// <utility>, which g++ 12 in C++20 mode does not pull in by itself.
#include <utility>

#include <boost/asio.hpp>
