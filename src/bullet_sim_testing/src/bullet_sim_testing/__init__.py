"""Helpers shared by the robots' rostests: ground truth from wall geometry, driving a robot."""
