#pragma once
// What RViz's MarkerArray display shows after applying arrays in order:
// DELETEALL empties it (every namespace, as RViz does), DELETE takes one
// marker (namespace and id) away, ADD and MODIFY put one in or replace it.
// Two viewers compare equal when they hold the same markers bit for bit,
// stamps aside (each array has its own).

#include <map>
#include <sstream>
#include <string>
#include <utility>

#include <ros/serialization.h>
#include <visualization_msgs/MarkerArray.h>

namespace brick_stack_sim {
namespace test {

class MarkerViewer {
 public:
  using Key = std::pair<std::string, int>;

  void apply(const visualization_msgs::MarkerArray& array) {
    using visualization_msgs::Marker;
    for (Marker marker : array.markers) {
      switch (marker.action) {
        case Marker::DELETEALL:
          shown_.clear();
          break;
        case Marker::DELETE:
          shown_.erase(Key(marker.ns, marker.id));
          break;
        default:  // ADD, MODIFY (the same value)
          marker.header.stamp = ros::Time();
          shown_[Key(marker.ns, marker.id)] = marker;
      }
    }
  }

  const std::map<Key, visualization_msgs::Marker>& shown() const { return shown_; }

  /// Empty when both show the same; else what differs, for a failure message.
  std::string differences(const MarkerViewer& other) const {
    std::ostringstream text;
    int listed = 0;
    for (const auto& [key, marker] : shown_) {
      const auto found = other.shown_.find(key);
      if (found == other.shown_.end()) {
        if (listed++ < 10) text << "only in the first: " << key.first << "/" << key.second << "\n";
      } else if (bytes(marker) != bytes(found->second)) {
        if (listed++ < 10) text << "differs: " << key.first << "/" << key.second << "\n";
      }
    }
    for (const auto& [key, marker] : other.shown_)
      if (!shown_.count(key) && listed++ < 10)
        text << "only in the second: " << key.first << "/" << key.second << "\n";
    if (listed > 10) text << "(" << listed << " in all)\n";
    return text.str();
  }

 private:
  static std::string bytes(const visualization_msgs::Marker& marker) {
    const uint32_t size = ros::serialization::serializationLength(marker);
    std::string buffer(size, '\0');
    ros::serialization::OStream stream(reinterpret_cast<uint8_t*>(&buffer[0]), size);
    ros::serialization::serialize(stream, marker);
    return buffer;
  }

  std::map<Key, visualization_msgs::Marker> shown_;
};

}  // namespace test
}  // namespace brick_stack_sim
