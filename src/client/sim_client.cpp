// SimClient's services: one connection per service, made at its first call,
// made again when it fails; a call that fails in transport is tried once more.
#include "brick_stack_sim/client/sim_client.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include <ros/service.h>
#include <ros/time.h>

namespace brick_stack_sim {
namespace client {

namespace {

/// `seconds` as a message shows it: "5", "0.5".
std::string formatSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", seconds);
  return text;
}

/// Waits up to `timeout` [s] of wall time for service `name`; 0 or less
/// looks once.
bool waitForService(const std::string& name, double timeout) {
  return ros::service::waitForService(name, ros::Duration(std::max(0.0, timeout)));
}

/// Every service of the node.
constexpr const char* kServices[] = {ros_adapter::kPlaceBrickService,
                                     ros_adapter::kRemoveBrickService,
                                     ros_adapter::kResetService,
                                     ros_adapter::kGetBricksService,
                                     ros_adapter::kPushBrickService,
                                     ros_adapter::kQueryPlacementService,
                                     ros_adapter::kQueryPlacementsService,
                                     ros_adapter::kPauseService,
                                     ros_adapter::kStepService,
                                     ros_adapter::kGraspBrickService,
                                     ros_adapter::kReleaseBrickService,
                                     ros_adapter::kSimulatePlanService};

std::string notAvailable(const std::string& service, double waited) {
  return "service " + service + " not available after " + formatSeconds(waited) + " s";
}

}  // namespace

SimClient::SimClient(ClientOptions options, ros::NodeHandle node_handle)
    : options_(std::move(options)), node_handle_(std::move(node_handle)) {}

std::string SimClient::resolve(const std::string& name) const {
  if (!name.empty() && name.front() == '/') return name;
  const std::string& ns = options_.sim_namespace;
  if (ns.empty()) return name;
  return ns.back() == '/' ? ns + name : ns + "/" + name;
}

CallResult SimClient::waitForNode(double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(std::max(0.0, timeout));
  CallResult result;
  for (const char* service : kServices) {
    const std::string name = resolve(service);
    if (!waitForService(name, (end - ros::WallTime::now()).toSec())) {
      result.service = name;
      result.message = notAvailable(name, timeout);
      return result;
    }
  }
  result.ok = result.reached = true;
  return result;
}

template <typename Service>
bool SimClient::connect(Slot slot, const std::string& name) {
  if (!waitForService(name, options_.service_wait)) return false;
  connections_[slot] = node_handle_.serviceClient<Service>(name, options_.persistent);
  return true;
}

template <typename Service>
Reply<typename Service::Response> SimClient::call(Slot slot, const char* name,
                                                  const typename Service::Request& request) {
  Reply<typename Service::Response> reply;
  reply.service = resolve(name);
  Service service;
  service.request = request;
  // Attempt 0 on the connection there is (made first when there is none, or
  // when a persistent one has dropped); attempt 1 on a new one.
  for (int attempt = 0; attempt < 2; ++attempt) {
    if ((attempt > 0 || !connections_[slot].isValid()) && !connect<Service>(slot, reply.service)) {
      reply.message = notAvailable(reply.service, options_.service_wait);
      return reply;
    }
    if (connections_[slot].call(service)) {
      reply.reached = true;
      reply.ok = service.response.success;
      reply.message = service.response.message;
      reply.response = std::move(service.response);
      return reply;
    }
  }
  reply.message = "call to service " + reply.service +
                  " failed in transport, also on a new connection (did the node go away?)";
  return reply;
}

Reply<PlaceBrick::Response> SimClient::placeBrick(const PlaceBrick::Request& request) {
  return call<PlaceBrick>(kPlace, ros_adapter::kPlaceBrickService, request);
}

Reply<RemoveBrick::Response> SimClient::removeBrick(const std::string& id) {
  RemoveBrick::Request request;
  request.id = id;
  return call<RemoveBrick>(kRemove, ros_adapter::kRemoveBrickService, request);
}

Reply<ResetScene::Response> SimClient::reset(const std::string& scene) {
  ResetScene::Request request;
  request.scene = scene;
  return call<ResetScene>(kReset, ros_adapter::kResetService, request);
}

Reply<GetBricks::Response> SimClient::getBricks(const std::vector<std::string>& ids) {
  GetBricks::Request request;
  request.ids = ids;
  return call<GetBricks>(kGet, ros_adapter::kGetBricksService, request);
}

Reply<PushBrick::Response> SimClient::pushBrick(const PushBrick::Request& request) {
  return call<PushBrick>(kPush, ros_adapter::kPushBrickService, request);
}

Reply<QueryPlacement::Response> SimClient::queryPlacement(const QueryPlacement::Request& request) {
  return call<QueryPlacement>(kQuery, ros_adapter::kQueryPlacementService, request);
}

Reply<QueryPlacements::Response> SimClient::queryPlacements(
    const QueryPlacements::Request& request) {
  return call<QueryPlacements>(kQueryMany, ros_adapter::kQueryPlacementsService, request);
}

Reply<std_srvs::SetBool::Response> SimClient::pause(bool paused) {
  std_srvs::SetBool::Request request;
  request.data = paused;
  return call<std_srvs::SetBool>(kPause, ros_adapter::kPauseService, request);
}

Reply<StepSimulation::Response> SimClient::step(std::uint32_t steps) {
  StepSimulation::Request request;
  request.steps = steps;
  return call<StepSimulation>(kStep, ros_adapter::kStepService, request);
}

Reply<GraspBrick::Response> SimClient::graspBrick(const std::string& id) {
  GraspBrick::Request request;
  request.id = id;
  return call<GraspBrick>(kGrasp, ros_adapter::kGraspBrickService, request);
}

Reply<ReleaseBrick::Response> SimClient::releaseBrick(const std::string& id,
                                                      const geometry_msgs::Twist& twist) {
  ReleaseBrick::Request request;
  request.id = id;
  request.twist = twist;
  return call<ReleaseBrick>(kRelease, ros_adapter::kReleaseBrickService, request);
}

Reply<SimulatePlan::Response> SimClient::simulatePlan(const SimulatePlan::Request& request) {
  return call<SimulatePlan>(kSimulatePlan, ros_adapter::kSimulatePlanService, request);
}

}  // namespace client
}  // namespace brick_stack_sim
