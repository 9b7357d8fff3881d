// Stelkropp's task system for Box2D v3 (b2WorldDef.enqueueTask / finishTask), part of the shim.
#include "shim.h"

#include <stdatomic.h>
#include <pthread.h>
#include <sched.h>
#include <semaphore.h>

// A small task system behind b2WorldDef.enqueueTask / finishTask. Box2D hands it at most
// B2_MAX_TASKS tasks per step; worker threads claim pending ones with a CAS and the stepping
// thread helps while it waits (so W workers = W-1 threads + the caller).
enum { TASK_FREE = 0, TASK_PENDING = 1, TASK_RUNNING = 2, TASK_DONE = 3 };

typedef struct S2Task
{
	b2TaskCallback* fn;
	void* ctx;
	atomic_int state;
} S2Task;

struct S2Pool
{
	pthread_t threads[B2_MAX_WORKERS];
	int threadCount;
	S2Task tasks[B2_MAX_TASKS];
	atomic_int used;
	atomic_int quit;
	sem_t wake;
};

static int s2_run_one( S2Pool* pool )
{
	int n = atomic_load( &pool->used );
	for ( int i = 0; i < n; ++i )
	{
		int expected = TASK_PENDING;
		if ( atomic_compare_exchange_strong( &pool->tasks[i].state, &expected, TASK_RUNNING ) )
		{
			pool->tasks[i].fn( pool->tasks[i].ctx );
			atomic_store( &pool->tasks[i].state, TASK_DONE );
			return 1;
		}
	}
	return 0;
}

static void* s2_worker( void* arg )
{
	S2Pool* pool = arg;
	for ( ;; )
	{
		sem_wait( &pool->wake );
		if ( atomic_load( &pool->quit ) )
		{
			return NULL;
		}
		while ( s2_run_one( pool ) )
		{
		}
	}
}

void* s2_enqueue( b2TaskCallback* fn, void* ctx, void* user )
{
	S2Pool* pool = user;
	int slot = atomic_fetch_add( &pool->used, 1 );
	if ( slot >= B2_MAX_TASKS )
	{
		// cannot happen (Box2D caps its tasks per step), but never index past the array
		atomic_fetch_sub( &pool->used, 1 );
		fn( ctx );
		return NULL;
	}
	S2Task* t = pool->tasks + slot;
	t->fn = fn;
	t->ctx = ctx;
	atomic_store( &t->state, TASK_PENDING ); // publishes fn/ctx (seq_cst store)
	sem_post( &pool->wake );
	return t;
}

void s2_finish( void* userTask, void* user )
{
	S2Pool* pool = user;
	S2Task* t = userTask;
	if ( t == NULL )
	{
		return;
	}
	while ( atomic_load( &t->state ) != TASK_DONE )
	{
		if ( s2_run_one( pool ) == 0 )
		{
			sched_yield();
		}
	}
}

S2Pool* s2_pool_create( int workers )
{
	S2Pool* pool = calloc( 1, sizeof( S2Pool ) );
	sem_init( &pool->wake, 0, 0 );
	pool->threadCount = workers - 1;
	for ( int i = 0; i < pool->threadCount; ++i )
	{
		pthread_create( pool->threads + i, NULL, s2_worker, pool );
	}
	return pool;
}

void s2_pool_destroy( S2Pool* pool )
{
	atomic_store( &pool->quit, 1 );
	for ( int i = 0; i < pool->threadCount; ++i )
	{
		sem_post( &pool->wake );
	}
	for ( int i = 0; i < pool->threadCount; ++i )
	{
		pthread_join( pool->threads[i], NULL );
	}
	sem_destroy( &pool->wake );
	free( pool );
}

void s2_pool_reset( S2Pool* pool )
{
	atomic_store( &pool->used, 0 ); // called between steps: every task of the last step has finished
}
