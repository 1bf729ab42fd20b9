// The motion store as the tool's commands use it, a header per concern: which clips a command's
// inputs name (store_clips.h), the policy and description options a store records
// (store_policy.h), the record that tells an unchanged source from a changed one
// (store_staleness.h), describing clips into a store (store_describe.h) and merging stores
// (store_merge.h).
#pragma once

#include "store_clips.h"
#include "store_describe.h"
#include "store_merge.h"
#include "store_policy.h"
#include "store_staleness.h"
