// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "numbers.h"

#include <CGAL/Fraction_traits.h>
#include <CGAL/number_utils.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cgal_subdiv {
namespace {

constexpr int max_exponent = 9999;

bool is_digits(const std::string& s)
{
  if(s.empty())
    return false;
  for(char c : s)
    if(!std::isdigit(static_cast<unsigned char>(c)))
      return false;
  return true;
}

// "+" or "-" at the front: removed, and the sign returned
int take_sign(std::string& s)
{
  if(!s.empty() && (s[0] == '+' || s[0] == '-')) {
    const int sign = s[0] == '-' ? -1 : 1;
    s.erase(0, 1);
    return sign;
  }
  return 1;
}

Exact power_of_ten(int k)
{
  Exact result(1), base(10);
  for(; k > 0; k >>= 1, base = base * base)
    if(k & 1)
      result = result * base;
  return result;
}

// a string of decimal digits, read nine at a time
Exact parse_digits(const std::string& digits)
{
  Exact value(0);
  for(std::size_t i = 0; i < digits.size(); i += 9) {
    const std::string chunk = digits.substr(i, 9);
    value = value * power_of_ten(static_cast<int>(chunk.size())) + Exact(std::stoi(chunk));
  }
  return value;
}

Exact parse_decimal(std::string s)
{
  const int sign = take_sign(s);
  int exponent = 0;
  const std::size_t e = s.find_first_of("eE");
  if(e != std::string::npos) {
    std::string exp_text = s.substr(e + 1);
    const int exp_sign = take_sign(exp_text);
    if(!is_digits(exp_text))
      throw std::invalid_argument("not a number");
    if(exp_text.size() > 4 || std::stoi(exp_text) > max_exponent)
      throw std::invalid_argument("exponent out of range");
    exponent = exp_sign * std::stoi(exp_text);
    s.erase(e);
  }
  std::string whole = s, fraction;
  const std::size_t dot = s.find('.');
  if(dot != std::string::npos) {
    whole = s.substr(0, dot);
    fraction = s.substr(dot + 1);
  }
  if((whole.empty() && fraction.empty()) || (!whole.empty() && !is_digits(whole)) ||
     (!fraction.empty() && !is_digits(fraction)))
    throw std::invalid_argument("not a number");
  exponent -= static_cast<int>(fraction.size());
  const Exact mantissa = parse_digits(whole + fraction);
  const Exact scaled =
    exponent >= 0 ? Exact(mantissa * power_of_ten(exponent)) : Exact(mantissa / power_of_ten(-exponent));
  return sign < 0 ? Exact(-scaled) : scaled;
}

} // namespace

Exact parse_number(const std::string& text)
{
  const std::size_t slash = text.find('/');
  if(slash == std::string::npos)
    return parse_decimal(text);
  std::string numerator = text.substr(0, slash), denominator = text.substr(slash + 1);
  const int sign = take_sign(numerator) * take_sign(denominator);
  if(!is_digits(numerator) || !is_digits(denominator))
    throw std::invalid_argument("not a number");
  const Exact d = parse_digits(denominator);
  if(d == Exact(0))
    throw std::invalid_argument("zero denominator");
  const Exact q = parse_digits(numerator) / d;
  return sign < 0 ? Exact(-q) : q;
}

int parse_int(const std::string& text)
{
  std::string digits = text;
  const int sign = take_sign(digits);
  if(!is_digits(digits))
    throw std::invalid_argument("not a whole number");
  if(digits.size() > 9)
    throw std::invalid_argument("too large");
  return sign * std::stoi(digits);
}

double nearest_double(const Exact& x)
{
  std::pair<double, double> range = CGAL::to_interval(x);
  if(!std::isfinite(range.first) || !std::isfinite(range.second)) {
    std::string text = format_exact(x);
    if(text.size() > 32)
      text = text.substr(0, 12) + "... (" + std::to_string(text.size()) + " characters)";
    throw Input_error("the number " + text + " is too large for a double (use --exact)");
  }
  // bisect until lo and hi are neighbours, then pick the nearer (ties: even)
  while(range.first != range.second &&
        std::nextafter(range.first, std::numeric_limits<double>::infinity()) != range.second) {
    const double mid = range.first / 2 + range.second / 2;
    (Exact(mid) <= x ? range.first : range.second) = mid;
  }
  if(range.first == range.second || Exact(range.first) == x)
    return range.first;
  if(Exact(range.second) == x)
    return range.second;
  const Exact mid = (Exact(range.first) + Exact(range.second)) / Exact(2);
  if(x < mid)
    return range.first;
  if(x > mid)
    return range.second;
  const double mantissa = std::ldexp(range.first, 52 - std::ilogb(range.first));
  return std::fmod(mantissa, 2.0) == 0 ? range.first : range.second;
}

std::string format_exact(const Exact& x)
{
  using Traits = CGAL::Fraction_traits<Exact>;
  typename Traits::Numerator_type numerator;
  typename Traits::Denominator_type denominator;
  typename Traits::Decompose()(x, numerator, denominator);
  std::ostringstream out;
  out << numerator;
  if(denominator != typename Traits::Denominator_type(1))
    out << '/' << denominator;
  return out.str();
}

std::string format_double(double x)
{
  if(x == 0)
    return "0"; // also for -0
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string json_number(double x)
{
  return std::isfinite(x) ? format_double(x) : "null";
}

std::string json_string(const std::string& text)
{
  std::string out = "\"";
  for(const char c : text) {
    if(c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if(static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

} // namespace cgal_subdiv
