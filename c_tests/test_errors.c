/* The error model: status text, the thread-local last-error message and its buffer protocol,
 * and the version macros against Cargo.toml's version (passed in by CMake). */
#define _POSIX_C_SOURCE 200809L /* pthread keys under -std=c11 */

#include <pthread.h>
#include <stdlib.h>

#include "check.h"

static void status_text(void) {
  hw_status s;
  for (s = HW_OK; s <= HW_ERR_OUT_OF_MEMORY; ++s) {
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
  CHECK(hw_mesh_from_indexed(NULL, 1, NULL, 0, NULL, 0, HW_BUILD_POLICY_STRICT, &mesh, NULL) ==
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

/* A message quoting a caller's string longer than HW_MAX_MESSAGE_SIZE is cut to fit it. */
static void long_messages_are_cut(void) {
  enum { NAME_LENGTH = 100000 };
  char *name = (char *)malloc(NAME_LENGTH + 1);
  static char message[HW_MAX_MESSAGE_SIZE];
  hw_mesh *mesh = hw_mesh_new();
  size_t needed = 0, length;
  CHECK(name != NULL && mesh != NULL);
  if (name == NULL || mesh == NULL) {
    free(name);
    hw_mesh_free(mesh);
    return;
  }
  memset(name, 'a', NAME_LENGTH);
  name[NAME_LENGTH] = '\0';
  CHECK(hw_mesh_attribute_remove(mesh, HW_ELEMENT_KIND_VERTEX, name) != HW_OK);
  CHECK(hw_last_error_message(NULL, 0, &needed) == HW_ERR_BUFFER_TOO_SMALL);
  CHECK(needed <= HW_MAX_MESSAGE_SIZE);
  CHECK(hw_last_error_message(message, sizeof message, NULL) == HW_OK);
  length = strlen(message);
  CHECK(length + 1 == needed);
  CHECK(strstr(message, "aaaa") != NULL);
  CHECK(length > strlen("… (cut)") &&
        strcmp(message + length - strlen("… (cut)"), "… (cut)") == 0);
  free(name);
  hw_mesh_free(mesh);
}

/* A failing call from a thread-local destructor that runs after halfwing's own thread-local
 * storage is gone (glibc runs pthread key destructors after the C++/Rust `thread_local` ones)
 * still returns its status instead of aborting the process. */
static pthread_key_t late_key;
static hw_status late_status = HW_OK;
static size_t late_count = 99;
static hw_status late_message_status = HW_ERR_PANIC;
static size_t late_needed = 0;

static void late_destructor(void *unused) {
  char message[64];
  (void)unused;
  late_status = hw_mesh_check(NULL);
  late_count = hw_mesh_n_vertices(NULL);
  late_message_status = hw_last_error_message(message, sizeof message, &late_needed);
}

static void *late_thread(void *unused) {
  (void)unused;
  /* A failure first, so that the last-error storage exists on this thread. */
  CHECK(hw_mesh_n_faces(NULL) == 0);
  pthread_setspecific(late_key, &late_key);
  return NULL;
}

static void failures_in_thread_local_destructors(void) {
  pthread_t thread;
  CHECK(pthread_key_create(&late_key, late_destructor) == 0);
  CHECK(pthread_create(&thread, NULL, late_thread, NULL) == 0);
  CHECK(pthread_join(thread, NULL) == 0);
  CHECK(late_status == HW_ERR_NULL_ARGUMENT);
  CHECK(late_count == 0);
  /* The message could not be kept; it reads empty (or, if the storage was still there, names
   * the argument). */
  CHECK(late_message_status == HW_OK);
  CHECK(late_needed >= 1);
  pthread_key_delete(late_key);
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
  long_messages_are_cut();
  failures_in_thread_local_destructors();
  version_matches_cargo_toml();
  return check_summary("test_errors");
}
