// The heavy third-party headers, precompiled once for every program this project builds.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <boost/graph/adjacency_list.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>
