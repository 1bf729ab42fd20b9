/// @file store.h
/// @brief Every public header of module `store`, motion libraries: the motion store, its records,
/// its transactional appends, and its clips read as a `search::MotionCollection`.
#pragma once

#include <deformseg/store/motion_store.h>
#include <deformseg/store/store_append.h>
#include <deformseg/store/store_record.h>
#include <deformseg/store/stored_motions.h>
