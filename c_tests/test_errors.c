/* The error model: status text, the thread-local last-error message and its buffer protocol,
 * and the version macros against Cargo.toml's version (passed in by CMake). */
#include <stdlib.h>

#include "check.h"

static void status_text(void) {
  hw_status s;
  for (s = HW_OK; s <= HW_ERR_NOT_FOUND; ++s) {
    const char *text = hw_status_str(s);
    CHECK(text != NULL && text[0] != '\0');
  }
  CHECK(strcmp(hw_status_str(HW_OK), "ok") == 0);
  CHECK(strcmp(hw_status_str(12345u), "unknown status") == 0);
}

static void last_error_buffer_protocol(void) {
  char small[4];
  char *message;
  size_t needed = 0;
  hw_mesh *mesh = NULL;
  /* Make a failure with a known message. */
  CHECK_STATUS(hw_last_error_message(NULL, 0, NULL), HW_ERR_BUFFER_TOO_SMALL, "");
  CHECK(hw_mesh_from_indexed(NULL, 1, NULL, 0, NULL, 0, HW_BUILD_STRICT, &mesh, NULL) ==
        HW_ERR_NULL_ARGUMENT);
  CHECK(mesh == NULL);
  /* Asking for the size writes nothing and reports it. */
  CHECK(hw_last_error_message(NULL, 0, &needed) == HW_ERR_BUFFER_TOO_SMALL);
  CHECK(needed > 1);
  memset(small, 'x', sizeof small);
  CHECK(hw_last_error_message(small, sizeof small, &needed) == HW_ERR_BUFFER_TOO_SMALL);
  CHECK(small[0] == 'x'); /* untouched on failure */
  message = (char *)malloc(needed);
  CHECK(message != NULL);
  if (message != NULL) {
    CHECK(hw_last_error_message(message, needed, NULL) == HW_OK);
    CHECK(strlen(message) + 1 == needed);
    CHECK(strstr(message, "positions") != NULL);
    /* Reading the message does not clear it. */
    CHECK(hw_last_error_message(message, needed, &needed) == HW_OK);
    CHECK(strstr(message, "positions") != NULL);
    free(message);
  }
}

static void version_matches_cargo_toml(void) {
  CHECK(HW_VERSION_MAJOR == EXPECTED_VERSION_MAJOR);
  CHECK(HW_VERSION_MINOR == EXPECTED_VERSION_MINOR);
  CHECK(HW_VERSION_PATCH == EXPECTED_VERSION_PATCH);
  CHECK(HW_VERSION_NUMBER ==
        EXPECTED_VERSION_MAJOR * 10000 + EXPECTED_VERSION_MINOR * 100 + EXPECTED_VERSION_PATCH);
  CHECK(hw_version_number() == HW_VERSION_NUMBER);
  CHECK(strcmp(hw_version_string(), EXPECTED_VERSION_STRING) == 0);
}

int main(void) {
  status_text();
  last_error_buffer_protocol();
  version_matches_cargo_toml();
  return check_summary("test_errors");
}
