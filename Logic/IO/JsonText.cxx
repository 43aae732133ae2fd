#include "IO/JsonText.h"

#include <algorithm>

namespace sgp
{

std::string DescribeJsonValue(const nlohmann::json& value)
{
  using Json = nlohmann::json;
  std::string dump = value.dump();
  if (dump.size() > 40)
    dump = dump.substr(0, 37) + "...";
  switch (value.type())
  {
    case Json::value_t::string:
      return "the string " + dump;
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "the number " + dump;
    case Json::value_t::boolean:
      return "the boolean " + dump;
    case Json::value_t::array:
      return "an array " + dump;
    case Json::value_t::object:
      return "an object " + dump;
    default:
      return "null";
  }
}

std::string JsonErrorMessage(const std::string& what)
{
  std::string message = what.substr(what.find(']') == std::string::npos ? 0 : what.find(']') + 2);
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

} // namespace sgp
